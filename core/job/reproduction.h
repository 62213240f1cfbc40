#pragma once
// The reproduction command of issue 4 (spec §8.5): the comparison on a seeded family of
// synthetic blades, summarised by the median and interquartile range of every reduction, so the
// paper's single-blade figures can be set against a distribution rather than one anecdote.

#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/compare/compare.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace bladeaxis::job {

struct ReproductionSpec {
    std::uint64_t seed = 2022;
    int blades = 36;
    compare::CompareOptions compare;
};

// One figure of one blade, e.g. {"stheta-best", "a_peak_acceleration_reduction_vs_original"}.
struct BladeFigures {
    std::string blade;
    std::size_t points = 0;
    std::size_t layers = 0;
    std::map<std::string, std::map<std::string, double>> figures; // method -> figure -> value
    std::string error; // non-empty when this blade could not be compared
    // Figures the comparison could not compute and why (compare::Comparison::missingFigures):
    // the medians that need them cover fewer blades (Spread::count).
    std::vector<std::string> missing;
};

struct Spread {
    double median = 0.0, q1 = 0.0, q3 = 0.0;
    std::size_t count = 0; // blades with this figure
};

struct ReproductionResult {
    ReproductionSpec spec;
    std::vector<BladeFigures> blades;
    std::map<std::string, std::map<std::string, Spread>> summary; // method -> figure -> spread
    double seconds = 0.0;
};

Result<ReproductionResult> runReproduction(const ReproductionSpec& spec, ProgressSink& progress,
                                           const CancelToken& cancel);

// The figures of one comparison (reductions against the original and, when present, against
// the quaternion baseline; reversals; T1/T2 gains; gap to the optimum; compute-time ratio).
std::map<std::string, std::map<std::string, double>>
comparisonFigures(const compare::Comparison& comparison);

// Median and quartiles (linear interpolation between order statistics).
Spread spreadOf(std::vector<double> values);

std::string reproductionJsonText(const ReproductionResult& result);
std::string reproductionCsv(const ReproductionResult& result);
std::string reproductionSummary(const ReproductionResult& result);

} // namespace bladeaxis::job

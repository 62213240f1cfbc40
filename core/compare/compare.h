#pragma once
// The comparison of issue 4 (spec §7-§9): every method on the same ball centres, evaluated by
// one pipeline (method_evaluation.h), so that the table a shop reads compares like with like.

#include "core/base/progress.h"
#include "core/compare/method_evaluation.h"
#include "core/scheduling/schedule_parameters.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::compare {

struct CompareOptions {
    scheduling::ScheduleParameters faithful = scheduling::faithfulPreset();
    scheduling::ScheduleParameters best = scheduling::bestPreset();
    // Rotary-limit factors for the machining-time sweep; empty: no sweep.
    std::vector<double> sweepFactors;
    bool optimum = true; // the smoothest schedule in the same channel (spec §9, optimal-qp)
    // The caller's own schedule of the same centres with `best` (a job has just made it) and
    // its wall time: reused as the stheta-best row instead of being scheduled again.
    const scheduling::ScheduleResult* bestSchedule = nullptr;
    double bestScheduleSeconds = 0.0;
};

// The fairness rule of spec §7.2: per metric, the best quaternion setting and its value.
struct FairnessEntry {
    std::string metric; // e.g. "A peak acceleration"
    std::string setting;
    double value = 0.0;
};

struct Comparison {
    scheduling::ScheduleResult reference; // stheta-best: its layers and channel frame the metrics
    std::vector<MethodResult> methods;    // original first, then in the order of the spec
    std::vector<MethodResult> quaternionSettings; // every feasible setting of the fairness rule
    std::vector<std::string> quaternionFailures;  // settings that could not be used, and why
    std::vector<FairnessEntry> quaternionFairness;
    // Why optimal-qp or optimal-lp is missing, one entry per missing method ("optimal-qp: layer
    // 3: ..."); empty when both were computed or not asked for.
    std::vector<std::string> optimumFailures;
    // The program's letter of each axis role, in X Y Z A B role order (MachineModel::letter),
    // for what a reader sees; metric names and machine-readable keys stay in roles.
    std::array<char, 5> letters = kinematics::kProgramLetters;

    const MethodResult* find(std::string_view method) const;
    // Every figure the comparison could not compute, with the reason: the optimum's failures
    // and each method whose T2 is missing ("stheta-best: T2: ..."), for the reports to print.
    std::vector<std::string> missingFigures() const;
    // The quaternion baseline's best value of a metric over its settings (fairness rule);
    // nullopt without a quaternion result.
    std::optional<double> bestQuaternion(std::string_view metric) const;
};

// The metrics of the fairness rule and of Table 2: "X peak velocity" ... "A peak acceleration",
// "T1", "T2". Velocities and accelerations in internal units (mm, rad, s).
std::vector<std::string> fairnessMetrics();
double metricValue(const MethodResult& method, std::string_view metric);

// `context.reference` is ignored: the comparison schedules its own reference.
Result<Comparison> compareMethods(EvaluationContext context, const CompareOptions& options,
                                  const CancelToken& cancel);

// (before - after) / before, the paper's "optimization ratio"; 0 when before is 0.
double reduction(double before, double after);

} // namespace bladeaxis::compare

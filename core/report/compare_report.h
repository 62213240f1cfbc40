#pragma once
// The comparison report of issue 4: compare.json, compare.csv and a self-contained report.html
// (the paper's Table 2 per method, reversals, T1/T2 and gains, gap to the optimum, compute time,
// and headless plots of the A axis, the S-theta channel and the X/Y/Z velocities).

#include "core/compare/compare.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::report {

// The comparison table (the paper's Table 2 per method) as data, so that report.html and the
// GUI show the same numbers, formatted the same way, from one definition.
struct CompareTableCell {
    std::optional<double> value; // in the column's unit (deg, mm, s, ms; fractions for ratios)
    std::string text;            // as the report prints it ("-" when there is no value)
    std::string note;            // what a reader may want on hover (settings, reductions)
};

// Which way a column's values improve, so that a reader can mark the best method.
enum class Better { Neither, Lower, Higher };

struct CompareTableColumn {
    std::string key;         // stable identifier ("A_peak_velocity", "t1_s", ...)
    std::string header;      // with the unit, as the report prints it
    std::string description; // what the column means
    Better better = Better::Neither;
};

struct CompareTable {
    std::vector<CompareTableColumn> columns;         // the first is the method name
    std::vector<std::vector<CompareTableCell>> rows; // one per comparison.methods, same order
    std::string reductionReference;                  // "quaternion", or "original" without it
    int columnOf(std::string_view key) const;        // -1 when absent
};

// Every column of the table: per-axis peaks (X, Y, Z, A), their reductions against the
// quaternion baseline (its best setting per metric, spec 7.2) and against the original, A
// reversals, T1 and T2 with their gains, the gaps to the optimum (spec 9.5) when it was
// computed, the minimum channel clearance and the compute time. report.html prints all of them.
CompareTable compareTable(const compare::Comparison& comparison);

nlohmann::json compareJson(const compare::Comparison& comparison);

// One row per method; units in the header. The raw values, then the table's derived figures
// (reductions, gains, gaps to the optimum) as fractions or ratios, keyed as in compareTable
// with "_vs_reference" naming the reference method.
std::string compareCsv(const compare::Comparison& comparison);

// The layers report.html draws in the S-theta plane, ascending: every layer of a path with at
// most 4, else the one where the original swings back the most, the middle one and the last.
std::vector<std::size_t> plottedLayers(const compare::Comparison& comparison);

// `title` names the program. Besides the table (every column of compareTable) and the A-axis
// and X/Y/Z plots, one S-theta figure per plottedLayers entry with every method's theta(S).
std::string compareHtml(const compare::Comparison& comparison, const std::string& title);

} // namespace bladeaxis::report

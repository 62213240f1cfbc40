#pragma once
// The comparison report of issue 4: compare.json, compare.csv and a self-contained report.html
// (the paper's Table 2 per method, reversals, T1/T2 and gains, gap to the optimum, compute time,
// and headless plots of the A axis, the S-theta channel and the X/Y/Z velocities).

#include "core/compare/compare.h"

#include <nlohmann/json.hpp>

#include <string>

namespace bladeaxis::report {

nlohmann::json compareJson(const compare::Comparison& comparison);

// One row per method; units in the header.
std::string compareCsv(const compare::Comparison& comparison);

// `title` names the program; layers to plot in the S-theta plane are chosen by the report
// (the first intermediate layer and the one where the original reverses most).
std::string compareHtml(const compare::Comparison& comparison, const std::string& title);

} // namespace bladeaxis::report

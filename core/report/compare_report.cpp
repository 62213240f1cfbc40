#include "core/report/compare_report.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/compare/channel_metrics.h"
#include "core/report/html_page.h"

#include <algorithm>
#include <array>
#include <functional>
#include <string_view>
#include <utility>

namespace bladeaxis::report {

namespace {

using compare::MethodResult;
using kinematics::AxisId;

constexpr std::array<AxisId, 4> kTableAxes{AxisId::X, AxisId::Y, AxisId::Z, AxisId::A};
constexpr std::size_t kAllLayersUpTo = 4; // report.html plots every layer of a short path

// Rotary values are reported in degrees, linear ones in mm.
double display(AxisId axis, double value) {
    return axis == AxisId::A || axis == AxisId::B ? units::radToDeg(value) : value;
}

const char* velocityUnit(AxisId axis) {
    return axis == AxisId::A ? "deg/s" : "mm/s";
}
const char* accelerationUnit(AxisId axis) {
    return axis == AxisId::A ? "deg/s^2" : "mm/s^2";
}

// The units as compare.json and compare.csv name them in their keys (docs/report-format.md).
const char* velocityKeyUnit(AxisId axis) {
    return axis == AxisId::A ? "deg_s" : "mm_s";
}
const char* accelerationKeyUnit(AxisId axis) {
    return axis == AxisId::A ? "deg_s2" : "mm_s2";
}

// theta'' energy (the integral of theta''^2 dS) in deg^2/mm^3, beside the other S-theta figures
// in degrees: it is held in rad^2/mm^3 inside.
double energyDegrees(double radians) {
    const double degreesPerRad = units::radToDeg(1.0);
    return radians * degreesPerRad * degreesPerRad;
}

// What every reduction against the quaternion baseline is measured against: for each metric,
// its best setting (fairness rule, spec 7.2), which need not be the setting of its row.
constexpr const char* kBestQuaternion = "best quaternion setting";
constexpr const char* kBestQuaternionKey = "best_quaternion_setting";

// A display unit as a key suffix: "deg/s^2" -> "deg_s2", "s" -> "s".
std::string keyUnit(std::string_view unit) {
    std::string key;
    for (char c : unit) {
        if (c == '/') {
            key += '_';
        } else if (c != '^') {
            key += c;
        }
    }
    return key;
}

// The model the axis figures assume, as the report's text names it.
std::string derivativeModel(const analysis::AxisProfile& profile) {
    const std::string feed = formatFixed(units::perSecondToPerMinute(profile.feed), 0) + " mm/min";
    if (profile.method == analysis::DerivativeMethod::Filtered) {
        return "each axis as a controller that smooths it over " +
               formatShortest(1e3 * profile.filterSeconds) +
               " ms (two moving averages, docs/figures.md) runs it at the programmed feed of " +
               feed;
    }
    return std::string("derivatives by the method '") + analysis::nameOf(profile.method) +
           "' at the programmed feed of " + feed;
}

// The program's letter of an axis role: what a reader of the table and the plots sees.
std::string letterOf(const compare::Comparison& comparison, AxisId axis) {
    return std::string(1, comparison.letters[static_cast<std::size_t>(axis)]);
}

// The role whose program letter is `letter` (the linear axes trade places on a table-B machine).
AxisId roleOfLetter(const compare::Comparison& comparison, char letter) {
    for (AxisId axis : kinematics::kAllAxes) {
        if (comparison.letters[static_cast<std::size_t>(axis)] == letter) {
            return axis;
        }
    }
    return AxisId::X;
}

// The linear axes in the program's X Y Z order.
std::array<AxisId, 3> linearAxesInProgramOrder(const compare::Comparison& comparison) {
    return {roleOfLetter(comparison, 'X'), roleOfLetter(comparison, 'Y'),
            roleOfLetter(comparison, 'Z')};
}

// The columns of the printed table: the linear axes in the program's order, then the table.
std::array<AxisId, 4> printedAxes(const compare::Comparison& comparison) {
    const auto linear = linearAxesInProgramOrder(comparison);
    return {linear[0], linear[1], linear[2], AxisId::A};
}

// A metric named by role ("A peak acceleration") as a reader names it ("B peak acceleration"
// on a table-B machine); the role name stays the metric's identifier in code and compare.json.
std::string displayMetric(const compare::Comparison& comparison, const std::string& metric) {
    for (AxisId axis : kinematics::kAllAxes) {
        if (metric.starts_with(std::string(kinematics::axisName(axis)) + " ")) {
            return letterOf(comparison, axis) + metric.substr(1);
        }
    }
    return metric;
}

// The quaternion baseline is the paper's reference for Table 2; without it, the original is.
const MethodResult& tableReference(const compare::Comparison& comparison) {
    const MethodResult* quaternion = comparison.find("quaternion");
    return quaternion != nullptr ? *quaternion : comparison.methods.front();
}

nlohmann::json methodJson(const MethodResult& method, const compare::Comparison& comparison) {
    const MethodResult& original = comparison.methods.front();
    nlohmann::json json;
    json["method"] = method.method;
    json["setting"] = method.setting;
    for (AxisId axis : kTableAxes) {
        const auto& series = method.profile.axis(axis);
        const auto& before = original.profile.axis(axis);
        json["axes"][kinematics::axisName(axis)] = {
            {std::string("peak_velocity_") + velocityKeyUnit(axis),
             display(axis, series.peakVelocity)},
            {std::string("peak_acceleration_") + accelerationKeyUnit(axis),
             display(axis, series.peakAcceleration)},
            {"velocity_reduction_vs_original",
             compare::reduction(before.peakVelocity, series.peakVelocity)},
            {"acceleration_reduction_vs_original",
             compare::reduction(before.peakAcceleration, series.peakAcceleration)}};
        const std::string name = kinematics::axisName(axis);
        // Against the quaternion baseline's best setting for this very metric (fairness rule),
        // named so: the quaternion row shows one setting, which may not be that one.
        if (auto q = comparison.bestQuaternion(name + " peak velocity")) {
            json["axes"][name][std::string("velocity_reduction_vs_") + kBestQuaternionKey] =
                compare::reduction(*q, series.peakVelocity);
        }
        if (auto q = comparison.bestQuaternion(name + " peak acceleration")) {
            json["axes"][name][std::string("acceleration_reduction_vs_") + kBestQuaternionKey] =
                compare::reduction(*q, series.peakAcceleration);
        }
    }
    json["a_reversals"] = method.profile.aReversals.count;
    json["a_travel_deg"] = units::radToDeg(method.profile.aReversals.travel);
    json["t1_s"] = method.t1.time;
    json["t1_gain_vs_original"] = compare::reduction(original.t1.time, method.t1.time);
    if (method.t2Jerk) {
        json["t2_jerk_heuristic_s"] = *method.t2Jerk;
    }
    if (!method.t2Failure.empty()) {
        json["t2_failure"] = method.t2Failure;
    }
    if (method.t2 && original.t2) {
        json["t2_s"] = *method.t2;
        json["t2_gain_vs_original"] = compare::reduction(*original.t2, *method.t2);
        json["t2_speedup_vs_original"] = *original.t2 / *method.t2 - 1.0;
    }
    json["channel"] = {
        {"min_clearance_deg", units::radToDeg(method.channel.minClearance)},
        {"samples_outside", method.channel.samplesOutside},
        {"peak_theta_dd_deg_mm2", units::radToDeg(method.channel.peakSecondDerivative)},
        {"theta_dd_energy_deg2_mm3", energyDegrees(method.channel.secondDerivativeEnergy)},
        {"theta_reversals", method.channel.thetaReversals}};
    if (!method.sweep.empty()) {
        json["rotary_limit_sweep"] = nlohmann::json::array();
        for (const compare::LimitSweepPoint& point : method.sweep) {
            nlohmann::json entry{{"factor", point.factor}, {"t1_s", point.t1}};
            if (point.t2) {
                entry["t2_s"] = *point.t2;
            }
            json["rotary_limit_sweep"].push_back(entry);
        }
    }
    json["timing"] = {{"compute_s", method.computeSeconds},
                      {"layer_stage_s", method.layerStageSeconds}};
    return json;
}

std::string percent(double fraction) {
    return formatFixed(100.0 * fraction, 1) + " %";
}

// The reference value of a metric for the reductions: the quaternion baseline's best setting
// for that metric when there is one, else the reference row's own value.
double referenceValue(const compare::Comparison& comparison, const MethodResult& reference,
                      std::string_view metric) {
    return comparison.bestQuaternion(metric).value_or(compare::metricValue(reference, metric));
}

CompareTableCell numberCell(double value, std::string text, std::string note = {}) {
    return {value, std::move(text), std::move(note)};
}

CompareTableCell emptyCell() {
    return {std::nullopt, "-", {}};
}

// A fairness entry's value in the units of the tables beside it (deg/s for A, mm/s for the
// linear axes, s for times): the metric is held in mm, rad, s inside.
std::pair<double, std::string> fairnessDisplayValue(const compare::FairnessEntry& entry) {
    for (AxisId axis : kTableAxes) {
        if (entry.metric.starts_with(kinematics::axisName(axis))) {
            const bool velocity = entry.metric.ends_with("velocity");
            return {display(axis, entry.value),
                    velocity ? velocityUnit(axis) : accelerationUnit(axis)};
        }
    }
    return {entry.value, "s"};
}

// A fairness entry in display units: "A peak velocity: <setting> (203.45 deg/s)".
std::string describeFairness(const compare::Comparison& comparison,
                             const compare::FairnessEntry& entry) {
    const auto [value, unit] = fairnessDisplayValue(entry);
    return displayMetric(comparison, entry.metric) + ": " + entry.setting + " (" +
           formatShortest(value) + " " + unit + ")";
}

// Which quaternion setting a reduction of `metric` is measured against (fairness rule).
std::string fairnessNote(const compare::Comparison& comparison, std::string_view metric) {
    for (const compare::FairnessEntry& entry : comparison.quaternionFairness) {
        if (entry.metric == metric) {
            return "against the best quaternion setting for this metric: " +
                   describeFairness(comparison, entry);
        }
    }
    return {};
}

std::string methodNote(const compare::Comparison& comparison, const MethodResult& method) {
    std::string note = "setting: " + method.setting;
    if (method.method == "quaternion" && !comparison.quaternionFairness.empty()) {
        note += " (the setting with the lowest " + letterOf(comparison, AxisId::A) +
                " peak acceleration)\nbest quaternion setting per metric (fairness rule, spec "
                "7.2):";
        for (const compare::FairnessEntry& entry : comparison.quaternionFairness) {
            note += "\n  " + describeFairness(comparison, entry);
        }
    }
    return note;
}

// A peak's reductions against the original and the quaternion baseline's best setting.
std::string peakNote(const compare::Comparison& comparison, const std::string& metric,
                     double value) {
    const MethodResult& original = comparison.methods.front();
    std::string note = "reduction vs original: " +
                       percent(compare::reduction(compare::metricValue(original, metric), value));
    if (auto best = comparison.bestQuaternion(metric)) {
        note += std::string("\nreduction vs ") + kBestQuaternion + ": " +
                percent(compare::reduction(*best, value));
    }
    return note;
}

using CellOf = std::function<CompareTableCell(const MethodResult&)>;

struct ColumnDefinition {
    CompareTableColumn column;
    CellOf cell;
};

void addPeakColumns(const compare::Comparison& comparison, std::vector<ColumnDefinition>& columns) {
    for (AxisId axis : printedAxes(comparison)) {
        const std::string name = kinematics::axisName(axis); // the key and the metric: the role
        const std::string shown = letterOf(comparison, axis);
        columns.push_back(
            {{name + "_peak_velocity", shown + " peak vel. (" + velocityUnit(axis) + ")",
              shown + " peak velocity at the programmed feed", Better::Lower},
             [&comparison, axis, name](const MethodResult& method) {
                 const double peak = method.profile.axis(axis).peakVelocity;
                 return numberCell(display(axis, peak), formatFixed(display(axis, peak), 2),
                                   peakNote(comparison, name + " peak velocity", peak));
             }});
        columns.push_back(
            {{name + "_peak_acceleration", shown + " peak acc. (" + accelerationUnit(axis) + ")",
              shown + " peak acceleration at the programmed feed", Better::Lower},
             [&comparison, axis, name](const MethodResult& method) {
                 const double peak = method.profile.axis(axis).peakAcceleration;
                 return numberCell(display(axis, peak), formatFixed(display(axis, peak), 1),
                                   peakNote(comparison, name + " peak acceleration", peak));
             }});
    }
}

void addReductionColumns(const compare::Comparison& comparison,
                         std::vector<ColumnDefinition>& columns) {
    const MethodResult& reference = tableReference(comparison);
    const MethodResult& original = comparison.methods.front();
    const std::string against =
        comparison.quaternionFairness.empty() ? reference.method : kBestQuaternion;
    for (AxisId axis : printedAxes(comparison)) {
        const std::string name = kinematics::axisName(axis); // the key and the metric: the role
        const std::string shown = letterOf(comparison, axis);
        for (const auto& [quantity, shortName] :
             {std::pair<std::string, std::string>{"velocity", "vel."}, {"acceleration", "acc."}}) {
            const std::string metric = name + " peak " + quantity;
            columns.push_back(
                {{name + "_" + quantity + "_reduction_vs_reference",
                  shown + " " + shortName + " reduction vs " + against,
                  "(reference - method) / reference; against the quaternion baseline, its best "
                  "setting for this metric (not necessarily its row's)",
                  Better::Higher},
                 [&comparison, &reference, metric](const MethodResult& method) {
                     const double value =
                         compare::reduction(referenceValue(comparison, reference, metric),
                                            compare::metricValue(method, metric));
                     return numberCell(value, percent(value), fairnessNote(comparison, metric));
                 }});
            if (&reference == &original) {
                continue; // the reference already is the original
            }
            columns.push_back({{name + "_" + quantity + "_reduction_vs_original",
                                shown + " " + shortName + " reduction vs original",
                                "(original - method) / original", Better::Higher},
                               [&original, metric](const MethodResult& method) {
                                   const double value =
                                       compare::reduction(compare::metricValue(original, metric),
                                                          compare::metricValue(method, metric));
                                   return numberCell(value, percent(value));
                               }});
        }
    }
}

void addTimeColumns(const compare::Comparison& comparison, std::vector<ColumnDefinition>& columns) {
    const MethodResult& original = comparison.methods.front();
    const std::string table = letterOf(comparison, AxisId::A);
    columns.push_back({{"a_reversals", table + " reversals",
                        "sign changes of the " + table + " velocity", Better::Lower},
                       [](const MethodResult& method) {
                           const std::size_t count = method.profile.aReversals.count;
                           return numberCell(static_cast<double>(count), std::to_string(count));
                       }});
    columns.push_back(
        {{"t1_s", "T1 constant feed (s)",
          "the whole pass at the one feed its slowest point allows (a bound, not a controller)",
          Better::Lower},
         [](const MethodResult& method) {
             return numberCell(method.t1.time, formatFixed(method.t1.time, 2));
         }});
    columns.push_back({{"t1_gain_vs_original", "T1 gain vs original", "(original - T1) / original",
                        Better::Higher},
                       [&original](const MethodResult& method) {
                           const double gain = compare::reduction(original.t1.time, method.t1.time);
                           return numberCell(gain, percent(gain));
                       }});
    columns.push_back(
        {{"t2_s", "T2 look-ahead (s)",
          "a look-ahead control, time-optimal under the axes' velocity and acceleration limits "
          "(TOPP-RA, grid-converged)",
          Better::Lower},
         [](const MethodResult& method) {
             return method.t2 ? numberCell(*method.t2, formatFixed(*method.t2, 2)) : emptyCell();
         }});
    columns.push_back({{"t2_gain_vs_original", "T2 gain vs original", "(original - T2) / original",
                        Better::Higher},
                       [&original](const MethodResult& method) {
                           if (!method.t2 || !original.t2) {
                               return emptyCell();
                           }
                           const double gain = compare::reduction(*original.t2, *method.t2);
                           return numberCell(gain, percent(gain));
                       }});
    columns.push_back(
        {{"block_by_block_s", "Block-by-block (s)",
          "each block planned alone, no blending across rotary blocks (LinuxCNC 2.9's planner)",
          Better::Lower},
         [](const MethodResult& method) {
             const double time = method.blockByBlock.time;
             return time > 0.0 ? numberCell(time, formatFixed(time, 2)) : emptyCell();
         }});
    columns.push_back(
        {{"t2_speedup_vs_original", "T2 efficiency vs original",
          "original / T2 - 1, the other reading of the paper's efficiency gain", Better::Higher},
         [&original](const MethodResult& method) {
             if (!method.t2 || !original.t2) {
                 return emptyCell();
             }
             const double speedup = *original.t2 / *method.t2 - 1.0;
             return numberCell(speedup, percent(speedup));
         }});
}

// The gaps to the optimum in the same channel (spec 9.5), as ratios: 1 is the optimum itself.
void addOptimumColumns(const compare::Comparison& comparison,
                       std::vector<ColumnDefinition>& columns) {
    if (const MethodResult* qp = comparison.find("optimal-qp");
        qp != nullptr && qp->channel.secondDerivativeEnergy > 0.0) {
        columns.push_back({{"theta_dd_energy_ratio_to_optimal_qp", "theta'' energy / optimal-qp",
                            "integral of theta''^2 over the layers, relative to the smoothest "
                            "schedule in the same channel",
                            Better::Lower},
                           [qp](const MethodResult& method) {
                               const double ratio = method.channel.secondDerivativeEnergy /
                                                    qp->channel.secondDerivativeEnergy;
                               return numberCell(ratio, formatFixed(ratio, 2));
                           }});
    }
    if (const MethodResult* lp = comparison.find("optimal-lp");
        lp != nullptr && lp->channel.peakSecondDerivative > 0.0) {
        columns.push_back({{"peak_theta_dd_ratio_to_optimal_lp", "peak theta'' / optimal-lp",
                            "peak |theta''| relative to the lowest-peak schedule in the same "
                            "channel",
                            Better::Lower},
                           [lp](const MethodResult& method) {
                               const double ratio = method.channel.peakSecondDerivative /
                                                    lp->channel.peakSecondDerivative;
                               return numberCell(ratio, formatFixed(ratio, 2));
                           }});
    }
}

std::vector<ColumnDefinition> tableColumns(const compare::Comparison& comparison) {
    std::vector<ColumnDefinition> columns;
    columns.push_back(
        {{"method", "method", "the method; its setting on hover"},
         [&comparison](const MethodResult& method) {
             return CompareTableCell{std::nullopt, method.method, methodNote(comparison, method)};
         }});
    addPeakColumns(comparison, columns);
    addReductionColumns(comparison, columns);
    addTimeColumns(comparison, columns);
    addOptimumColumns(comparison, columns);
    columns.push_back({{"min_clearance_deg", "min channel clearance (deg)",
                        "smallest distance of theta to the raw channel's bounds; negative: outside",
                        Better::Higher},
                       [](const MethodResult& method) {
                           const double degrees = units::radToDeg(method.channel.minClearance);
                           return numberCell(degrees, formatFixed(degrees, 3));
                       }});
    columns.push_back({{"compute_ms", "compute (ms)", "wall time of the method itself"},
                       [](const MethodResult& method) {
                           const double ms = 1000.0 * method.computeSeconds;
                           return numberCell(ms, formatFixed(ms, 2));
                       }});
    return columns;
}

struct PrintedTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

// Every column of compareTable, as the GUI shows it: one definition for both.
PrintedTable printedTable(const CompareTable& table) {
    PrintedTable printed;
    for (const CompareTableColumn& column : table.columns) {
        printed.header.push_back(column.header);
    }
    for (const std::vector<CompareTableCell>& row : table.rows) {
        std::vector<std::string> texts;
        for (const CompareTableCell& cell : row) {
            texts.push_back(cell.text);
        }
        printed.rows.push_back(std::move(texts));
    }
    return printed;
}

Plot axisPlot(const compare::Comparison& comparison, AxisId axis, int derivative) {
    static constexpr std::array<const char*, 3> kNames{"position", "velocity", "acceleration"};
    Plot plot;
    plot.title = letterOf(comparison, axis) + " " + kNames[derivative];
    plot.xLabel = "time at the programmed feed (s)";
    const bool rotary = axis == AxisId::A;
    const std::array<std::string, 3> units{rotary ? "deg" : "mm", velocityUnit(axis),
                                           accelerationUnit(axis)};
    plot.yLabel = units[derivative];
    for (const MethodResult& method : comparison.methods) {
        const auto& series = method.profile.axis(axis);
        const std::size_t n = method.profile.sampleRecord.size();
        const std::vector<double> values = derivative == 0   ? method.profile.positions(axis)
                                           : derivative == 1 ? series.velocities(n)
                                                             : series.accelerations(n);
        PlotSeries line;
        line.name = method.method;
        line.x = method.profile.times();
        for (double value : values) {
            line.y.push_back(display(axis, value));
        }
        line.dashed = method.method == "original";
        plot.series.push_back(std::move(line));
    }
    return plot;
}

// The layer where the original reverses most: the one a reviewer wants to see first.
std::size_t mostReciprocatingLayer(const compare::Comparison& comparison) {
    const auto thetas =
        compare::layerThetas(comparison.reference, comparison.methods.front().toolAxes);
    std::size_t best = 0;
    double worst = -1.0;
    for (std::size_t k = 0; k < thetas.size(); ++k) {
        double backwards = 0.0;
        for (std::size_t j = 1; j < thetas[k].size(); ++j) {
            backwards += std::max(0.0, thetas[k][j - 1] - thetas[k][j]);
        }
        if (backwards > worst) {
            worst = backwards;
            best = k;
        }
    }
    return best;
}

Plot channelPlot(const compare::Comparison& comparison, std::size_t k) {
    const scheduling::LayerResult& layer = comparison.reference.layers[k];
    Plot plot;
    plot.title = "Layer " + std::to_string(k + 1) + " in the S-theta plane";
    plot.xLabel = "S (mm)";
    plot.yLabel = "theta (deg)";
    auto degrees = [](const std::vector<double>& values) {
        std::vector<double> out;
        for (double value : values) {
            out.push_back(units::radToDeg(value));
        }
        return out;
    };
    plot.bands.push_back(
        {"raw channel", layer.s, degrees(layer.thetaMin), degrees(layer.thetaMax), "#c6dbef", 0.6});
    plot.bands.push_back(
        {"monotone hull", layer.s, degrees(layer.lo), degrees(layer.hi), "#6baed6", 0.35});
    for (const MethodResult& method : comparison.methods) {
        const auto thetas = compare::layerThetas(comparison.reference, method.toolAxes);
        PlotSeries line;
        line.name = method.method;
        line.x = layer.s;
        line.y = degrees(thetas[k]);
        line.dashed = method.method == "original";
        plot.series.push_back(std::move(line));
    }
    return plot;
}

std::vector<std::string> sweepHeader(const MethodResult& original) {
    std::vector<std::string> header{"method"};
    for (const compare::LimitSweepPoint& point : original.sweep) {
        header.push_back("T1 at x" + formatTrimmed(point.factor, 2) + " (s)");
        if (point.t2) {
            header.push_back("T2 at x" + formatTrimmed(point.factor, 2) + " (s)");
        }
    }
    return header;
}

std::vector<std::vector<std::string>> sweepRows(const compare::Comparison& comparison) {
    std::vector<std::vector<std::string>> rows;
    for (const MethodResult& method : comparison.methods) {
        std::vector<std::string> row{method.method};
        for (const compare::LimitSweepPoint& point : method.sweep) {
            row.push_back(formatFixed(point.t1, 2));
            if (point.t2) {
                row.push_back(formatFixed(*point.t2, 2));
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

// The table's derived figures (reductions, gains, gaps to the optimum), as fractions or ratios:
// compare.csv appends them to the raw values so that it carries what report.html shows.
std::vector<std::size_t> derivedColumns(const CompareTable& table) {
    std::vector<std::size_t> derived;
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
        const std::string& key = table.columns[i].key;
        if (key.ends_with("_vs_reference") || key.ends_with("_vs_original") ||
            key.find("_ratio_to_optimal_") != std::string::npos) {
            derived.push_back(i);
        }
    }
    return derived;
}

// A column key for the CSV, naming the reduction's reference method ("..._vs_quaternion").
std::string csvKey(const CompareTable& table, std::size_t column) {
    std::string key = table.columns[column].key;
    constexpr std::string_view kReference = "_vs_reference";
    if (key.ends_with(kReference)) {
        key.replace(key.size() - kReference.size(), kReference.size(),
                    "_vs_" + table.reductionReference);
    }
    return key;
}

} // namespace

std::vector<std::size_t> plottedLayers(const compare::Comparison& comparison) {
    const std::size_t count = comparison.reference.layers.size();
    std::vector<std::size_t> layers;
    if (count <= kAllLayersUpTo) {
        for (std::size_t k = 0; k < count; ++k) {
            layers.push_back(k);
        }
        return layers;
    }
    layers = {mostReciprocatingLayer(comparison), count / 2, count - 1};
    std::sort(layers.begin(), layers.end());
    layers.erase(std::unique(layers.begin(), layers.end()), layers.end());
    return layers;
}

int CompareTable::columnOf(std::string_view key) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
        if (columns[i].key == key) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

CompareTable compareTable(const compare::Comparison& comparison) {
    CompareTable table;
    table.reductionReference = comparison.quaternionFairness.empty()
                                   ? tableReference(comparison).method
                                   : std::string(kBestQuaternionKey);
    const std::vector<ColumnDefinition> columns = tableColumns(comparison);
    for (const ColumnDefinition& definition : columns) {
        table.columns.push_back(definition.column);
    }
    for (const MethodResult& method : comparison.methods) {
        std::vector<CompareTableCell> row;
        row.reserve(columns.size());
        for (const ColumnDefinition& definition : columns) {
            row.push_back(definition.cell(method));
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

nlohmann::json compareJson(const compare::Comparison& comparison) {
    nlohmann::json json;
    json["layers"] = comparison.reference.layers.size();
    json["table_reference"] = tableReference(comparison).method;
    json["methods"] = nlohmann::json::array();
    for (const MethodResult& method : comparison.methods) {
        json["methods"].push_back(methodJson(method, comparison));
    }
    json["quaternion_settings"] = nlohmann::json::array();
    for (const MethodResult& setting : comparison.quaternionSettings) {
        json["quaternion_settings"].push_back(methodJson(setting, comparison));
    }
    for (const compare::FairnessEntry& entry : comparison.quaternionFairness) {
        const auto [value, unit] = fairnessDisplayValue(entry);
        json["quaternion_fairness"][entry.metric] = {{"setting", entry.setting},
                                                     {"value_" + keyUnit(unit), value}};
    }
    json["quaternion_failures"] = comparison.quaternionFailures;
    json["optimum_failures"] = comparison.optimumFailures;
    json["missing_figures"] = comparison.missingFigures();
    return json;
}

std::string compareCsv(const compare::Comparison& comparison) {
    const CompareTable table = compareTable(comparison);
    const std::vector<std::size_t> derived = derivedColumns(table);
    std::string csv = "method,setting";
    for (AxisId axis : kTableAxes) {
        const std::string name = kinematics::axisName(axis);
        csv += "," + name + "_peak_velocity_" + velocityKeyUnit(axis) + "," + name +
               "_peak_acceleration_" + accelerationKeyUnit(axis);
    }
    csv += ",a_reversals,t1_s,t2_s,min_clearance_deg,peak_theta_dd_deg_mm2,compute_s";
    for (std::size_t column : derived) {
        csv += "," + csvKey(table, column);
    }
    csv += "\n";
    for (std::size_t row = 0; row < comparison.methods.size(); ++row) {
        const MethodResult& method = comparison.methods[row];
        csv += method.method + ",\"" + method.setting + "\"";
        for (AxisId axis : kTableAxes) {
            const auto& series = method.profile.axis(axis);
            csv += "," + formatShortest(display(axis, series.peakVelocity)) + "," +
                   formatShortest(display(axis, series.peakAcceleration));
        }
        csv += "," + std::to_string(method.profile.aReversals.count) + "," +
               formatShortest(method.t1.time) + "," +
               (method.t2 ? formatShortest(*method.t2) : std::string()) + "," +
               formatShortest(units::radToDeg(method.channel.minClearance)) + "," +
               formatShortest(units::radToDeg(method.channel.peakSecondDerivative)) + "," +
               formatShortest(method.computeSeconds);
        for (std::size_t column : derived) {
            const auto& value = table.rows[row][column].value;
            csv += "," + (value ? formatShortest(*value) : std::string());
        }
        csv += "\n";
    }
    return csv;
}

std::string compareHtml(const compare::Comparison& comparison, const std::string& title) {
    HtmlPage page("BladeAxis comparison: " + title);
    const MethodResult& original = comparison.methods.front();
    const std::string table = letterOf(comparison, AxisId::A);
    page.paragraph("Every method keeps the same ball centres and is evaluated by the same "
                   "pipeline: inverse kinematics with " +
                   table + " continuous, " + derivativeModel(original.profile) +
                   ", T1 by constant-feed scaling to the machine limits. Reductions are "
                   "(reference - method) / reference.");
    page.heading("Peaks, reversals and machining time");
    if (!comparison.quaternionFairness.empty()) {
        page.paragraph("The quaternion row is its setting with the lowest peak " + table +
                       " acceleration; "
                       "every reduction \"vs best quaternion setting\" is measured against the "
                       "quaternion baseline's best setting for that metric (fairness rule, spec "
                       "7.2), which may be another setting than the row's; they are listed "
                       "below the table.");
    }
    const auto [header, rows] = printedTable(compareTable(comparison));
    page.table(header, rows);
    if (const auto missing = comparison.missingFigures(); !missing.empty()) {
        std::string text = "Not computed (the table shows \"-\" or leaves the method out):";
        for (const std::string& reason : missing) {
            text += " " + reason + ".";
        }
        page.paragraph(text);
    }
    if (!comparison.quaternionFairness.empty()) {
        std::vector<std::vector<std::string>> fairness;
        for (const compare::FairnessEntry& entry : comparison.quaternionFairness) {
            const auto [value, unit] = fairnessDisplayValue(entry);
            fairness.push_back({displayMetric(comparison, entry.metric), entry.setting,
                                formatShortest(value) + " " + unit});
        }
        page.table({"metric", "best quaternion setting", "value"}, fairness);
    }
    if (!original.sweep.empty()) {
        page.heading("Machining time against the rotary-axis limits");
        page.paragraph("The " + table +
                       "-axis velocity, acceleration and jerk limits of the machine file "
                       "scaled by the factor; the linear axes unchanged.");
        page.table(sweepHeader(original), sweepRows(comparison));
    }
    page.heading(table + " axis against time");
    for (int derivative = 0; derivative < 3; ++derivative) {
        page.figure(axisPlot(comparison, AxisId::A, derivative));
    }
    page.heading("Layers in the S-theta plane");
    page.paragraph("Raw channel, monotone hull and every method's theta(S).");
    const std::size_t reciprocating = mostReciprocatingLayer(comparison);
    const std::size_t layers = comparison.reference.layers.size();
    for (std::size_t layer : plottedLayers(comparison)) {
        std::string caption =
            "Layer " + std::to_string(layer + 1) + " of " + std::to_string(layers);
        if (layer == reciprocating) {
            caption += ", where the original orientation swings back the most";
        }
        page.figure(channelPlot(comparison, layer), caption + ".");
    }
    page.heading("Linear axes");
    for (AxisId axis : linearAxesInProgramOrder(comparison)) {
        page.figure(axisPlot(comparison, axis, 1));
    }
    return page.str();
}

} // namespace bladeaxis::report

#include "core/report/compare_report.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/compare/channel_metrics.h"
#include "core/report/html_page.h"

#include <algorithm>

namespace bladeaxis::report {

namespace {

using compare::MethodResult;
using kinematics::AxisId;

constexpr std::array<AxisId, 4> kTableAxes{AxisId::X, AxisId::Y, AxisId::Z, AxisId::A};

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
            {"peak_velocity", display(axis, series.peakVelocity)},
            {"peak_acceleration", display(axis, series.peakAcceleration)},
            {"velocity_reduction_vs_original",
             compare::reduction(before.peakVelocity, series.peakVelocity)},
            {"acceleration_reduction_vs_original",
             compare::reduction(before.peakAcceleration, series.peakAcceleration)}};
        const std::string name = kinematics::axisName(axis);
        // Against the quaternion baseline's best setting for this very metric (fairness rule).
        if (auto q = comparison.bestQuaternion(name + " peak velocity")) {
            json["axes"][name]["velocity_reduction_vs_quaternion"] =
                compare::reduction(*q, series.peakVelocity);
        }
        if (auto q = comparison.bestQuaternion(name + " peak acceleration")) {
            json["axes"][name]["acceleration_reduction_vs_quaternion"] =
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
    if (method.t2 && original.t2) {
        json["t2_s"] = *method.t2;
        json["t2_gain_vs_original"] = compare::reduction(*original.t2, *method.t2);
        json["t2_speedup_vs_original"] = *original.t2 / *method.t2 - 1.0;
    }
    json["channel"] = {
        {"min_clearance_deg", units::radToDeg(method.channel.minClearance)},
        {"samples_outside", method.channel.samplesOutside},
        {"peak_theta_dd_deg_mm2", units::radToDeg(method.channel.peakSecondDerivative)},
        {"theta_dd_energy", method.channel.secondDerivativeEnergy},
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
    json["timing"] = {{"compute_s", method.computeSeconds}};
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

std::vector<std::string> tableRow(const compare::Comparison& comparison, const MethodResult& method,
                                  const MethodResult& reference, const MethodResult& original) {
    std::vector<std::string> row{method.method};
    for (AxisId axis : kTableAxes) {
        const auto& series = method.profile.axis(axis);
        row.push_back(formatFixed(display(axis, series.peakVelocity), 2));
        row.push_back(formatFixed(display(axis, series.peakAcceleration), 1));
    }
    const auto& a = method.profile.axis(AxisId::A);
    row.push_back(percent(compare::reduction(
        referenceValue(comparison, reference, "A peak velocity"), a.peakVelocity)));
    row.push_back(percent(compare::reduction(
        referenceValue(comparison, reference, "A peak acceleration"), a.peakAcceleration)));
    row.push_back(std::to_string(method.profile.aReversals.count));
    row.push_back(formatFixed(method.t1.time, 2));
    row.push_back(percent(compare::reduction(original.t1.time, method.t1.time)));
    row.push_back(method.t2 ? formatFixed(*method.t2, 2) : "-");
    row.push_back(formatFixed(units::radToDeg(method.channel.minClearance), 3));
    row.push_back(formatFixed(1000.0 * method.computeSeconds, 2));
    return row;
}

std::vector<std::string> tableHeader(const compare::Comparison& comparison) {
    std::vector<std::string> header{"method"};
    for (AxisId axis : kTableAxes) {
        const std::string name = kinematics::axisName(axis);
        header.push_back(name + " peak vel. (" + velocityUnit(axis) + ")");
        header.push_back(name + " peak acc. (" + accelerationUnit(axis) + ")");
    }
    const std::string against = tableReference(comparison).method;
    header.insert(header.end(), {"A vel. reduction vs " + against, "A acc. reduction vs " + against,
                                 "A reversals", "T1 (s)", "T1 gain vs original", "T2 (s)",
                                 "min channel clearance (deg)", "compute (ms)"});
    return header;
}

Plot axisPlot(const compare::Comparison& comparison, AxisId axis, int derivative) {
    static constexpr std::array<const char*, 3> kNames{"position", "velocity", "acceleration"};
    Plot plot;
    plot.title = std::string(kinematics::axisName(axis)) + " " + kNames[derivative];
    plot.xLabel = "time at the programmed feed (s)";
    const bool rotary = axis == AxisId::A;
    const std::array<std::string, 3> units{rotary ? "deg" : "mm", velocityUnit(axis),
                                           accelerationUnit(axis)};
    plot.yLabel = units[derivative];
    for (const MethodResult& method : comparison.methods) {
        const auto& series = method.profile.axis(axis);
        const std::vector<double>& values = derivative == 0   ? series.position
                                            : derivative == 1 ? series.velocity
                                                              : series.acceleration;
        PlotSeries line;
        line.name = method.method;
        line.x = method.profile.time;
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

} // namespace

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
        json["quaternion_fairness"][entry.metric] = {{"setting", entry.setting},
                                                     {"value", entry.value}};
    }
    json["quaternion_failures"] = comparison.quaternionFailures;
    return json;
}

std::string compareCsv(const compare::Comparison& comparison) {
    std::string csv = "method,setting";
    for (AxisId axis : kTableAxes) {
        const std::string name = kinematics::axisName(axis);
        csv += "," + name + "_peak_velocity_" + velocityUnit(axis) + "," + name +
               "_peak_acceleration_" + accelerationUnit(axis);
    }
    csv += ",a_reversals,t1_s,t2_s,min_clearance_deg,peak_theta_dd_deg_mm2,compute_s\n";
    for (const MethodResult& method : comparison.methods) {
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
               formatShortest(method.computeSeconds) + "\n";
    }
    return csv;
}

std::string compareHtml(const compare::Comparison& comparison, const std::string& title) {
    HtmlPage page("BladeAxis comparison: " + title);
    const MethodResult& original = comparison.methods.front();
    const MethodResult& reference = tableReference(comparison);
    page.paragraph("Every method keeps the same ball centres and is evaluated by the same "
                   "pipeline: inverse kinematics with A continuous, cubic-spline derivatives at "
                   "the programmed feed of " +
                   formatFixed(units::perSecondToPerMinute(original.profile.feed), 0) +
                   " mm/min, T1 by constant-feed scaling to the machine limits. Reductions are "
                   "(reference - method) / reference.");
    page.heading("Peaks, reversals and machining time");
    if (!comparison.quaternionFairness.empty()) {
        page.paragraph("The quaternion row is its setting with the lowest peak A acceleration; "
                       "every reduction against the quaternion baseline uses its best setting "
                       "for that metric (fairness rule, spec 7.2), listed below the table.");
    }
    std::vector<std::vector<std::string>> rows;
    for (const MethodResult& method : comparison.methods) {
        rows.push_back(tableRow(comparison, method, reference, original));
    }
    page.table(tableHeader(comparison), rows);
    if (!comparison.quaternionFairness.empty()) {
        std::vector<std::vector<std::string>> fairness;
        for (const compare::FairnessEntry& entry : comparison.quaternionFairness) {
            fairness.push_back({entry.metric, entry.setting, formatShortest(entry.value)});
        }
        page.table({"metric (internal units)", "best quaternion setting", "value"}, fairness);
    }
    if (!original.sweep.empty()) {
        page.heading("Machining time against the rotary-axis limits");
        page.paragraph("The A-axis velocity, acceleration and jerk limits of the machine file "
                       "scaled by the factor; the linear axes unchanged.");
        page.table(sweepHeader(original), sweepRows(comparison));
    }
    page.heading("A axis against time");
    for (int derivative = 0; derivative < 3; ++derivative) {
        page.figure(axisPlot(comparison, AxisId::A, derivative));
    }
    page.heading("Layers in the S-theta plane");
    const std::size_t layer = mostReciprocatingLayer(comparison);
    page.figure(channelPlot(comparison, layer),
                "The layer where the original orientation swings back the most: raw channel, "
                "monotone hull and every method's theta(S).");
    page.heading("Linear axes");
    for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z}) {
        page.figure(axisPlot(comparison, axis, 1));
    }
    return page.str();
}

} // namespace bladeaxis::report

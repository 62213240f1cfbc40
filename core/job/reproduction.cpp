#include "core/job/reproduction.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/blade/presets.h"
#include "core/kinematics/kinematics.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace bladeaxis::job {

namespace {

using compare::MethodResult;
using kinematics::AxisId;

void addReductions(const MethodResult& method, const MethodResult& reference,
                   const std::string& suffix, std::map<std::string, double>& figures) {
    for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z, AxisId::A}) {
        std::string name = kinematics::axisName(axis);
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        const auto& after = method.profile.axis(axis);
        const auto& before = reference.profile.axis(axis);
        figures[name + "_peak_velocity_reduction_vs_" + suffix] =
            compare::reduction(before.peakVelocity, after.peakVelocity);
        figures[name + "_peak_acceleration_reduction_vs_" + suffix] =
            compare::reduction(before.peakAcceleration, after.peakAcceleration);
    }
}

// Against the quaternion baseline's best setting for each metric (the fairness rule, §7.2).
void addQuaternionReductions(const MethodResult& method, const compare::Comparison& comparison,
                             std::map<std::string, double>& figures) {
    for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z, AxisId::A}) {
        const std::string name = kinematics::axisName(axis);
        std::string lower = name;
        lower[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(lower[0])));
        for (const char* quantity : {"velocity", "acceleration"}) {
            const std::string metric = name + " peak " + quantity;
            if (auto best = comparison.bestQuaternion(metric)) {
                figures[lower + "_peak_" + quantity + "_reduction_vs_quaternion"] =
                    compare::reduction(*best, compare::metricValue(method, metric));
            }
        }
    }
    if (auto best = comparison.bestQuaternion("A peak acceleration"); best && *best > 0.0) {
        figures["a_peak_acceleration_ratio_to_quaternion"] =
            compare::metricValue(method, "A peak acceleration") / *best;
    }
}

std::map<std::string, double> figuresOf(const MethodResult& method,
                                        const compare::Comparison& comparison) {
    std::map<std::string, double> figures;
    const MethodResult& original = comparison.methods.front();
    figures["a_reversals"] = static_cast<double>(method.profile.aReversals.count);
    figures["min_channel_clearance_deg"] = units::radToDeg(method.channel.minClearance);
    if (&method == &original) {
        return figures;
    }
    addReductions(method, original, "original", figures);
    figures["t1_gain_vs_original"] = compare::reduction(original.t1.time, method.t1.time);
    if (method.t2 && original.t2) {
        figures["t2_gain_vs_original"] = compare::reduction(*original.t2, *method.t2);
    }
    if (method.method != "quaternion") {
        addQuaternionReductions(method, comparison, figures);
    }
    const MethodResult* lp = comparison.find("optimal-lp");
    if (lp != nullptr && lp != &method && lp->channel.peakSecondDerivative > 0.0) {
        figures["peak_theta_dd_ratio_to_optimal_lp"] =
            method.channel.peakSecondDerivative / lp->channel.peakSecondDerivative;
    }
    const MethodResult* qp = comparison.find("optimal-qp");
    if (qp != nullptr && qp != &method && qp->channel.peakSecondDerivative > 0.0) {
        // Gaps to the smoothest schedule in the same channel (spec §9.5).
        figures["peak_theta_dd_ratio_to_optimal_qp"] =
            method.channel.peakSecondDerivative / qp->channel.peakSecondDerivative;
        figures["theta_dd_energy_ratio_to_optimal_qp"] =
            method.channel.secondDerivativeEnergy / qp->channel.secondDerivativeEnergy;
    }
    if (qp != nullptr && qp != &method && method.computeSeconds > 0.0) {
        figures["compute_speedup_vs_optimal_qp"] = qp->computeSeconds / method.computeSeconds;
    }
    if (qp != nullptr && qp != &method && method.layerStageSeconds > 0.0) {
        // Like for like, per layer (spec §8.5): both sides without the shared path preparation.
        figures["compute_speedup_per_layer_vs_optimal_qp"] =
            qp->layerStageSeconds / method.layerStageSeconds;
    }
    return figures;
}

// The member's path as a program would carry it: CL records plus machine axes by IK.
Result<compare::Comparison> compareMember(const blade::FamilyMember& member,
                                          const kinematics::MachineModel& machine,
                                          const compare::CompareOptions& options,
                                          const CancelToken& cancel, BladeFigures& figures) {
    auto bladeModel = blade::Blade::create(member.blade);
    if (!bladeModel) {
        return std::unexpected(bladeModel.error());
    }
    auto generated = blade::generateHelicalPath(*bladeModel, member.path);
    if (!generated) {
        return std::unexpected(generated.error());
    }
    const auto& records = generated->path.records;
    std::vector<kinematics::ToolPose> poses;
    poses.reserve(records.size());
    for (const auto& record : records) {
        poses.push_back({record.tip, record.axis});
    }
    auto solved = kinematics::inverseKinematicsAlong(machine.chain, poses, 0.0);
    if (solved.failedIndex) {
        return std::unexpected(solved.failure);
    }
    compare::EvaluationContext context;
    context.pass = records;
    context.originalAxes = solved.axes;
    context.toolRadius = member.path.toolRadius;
    context.machine = &machine;
    figures.points = records.size();
    return compare::compareMethods(context, options, cancel);
}

double quantile(const std::vector<double>& sorted, double q) {
    const double position = q * static_cast<double>(sorted.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    const double fraction = position - static_cast<double>(below);
    return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

void summarise(ReproductionResult& result) {
    std::map<std::string, std::map<std::string, std::vector<double>>> values;
    for (const BladeFigures& blade : result.blades) {
        for (const auto& [method, figures] : blade.figures) {
            for (const auto& [name, value] : figures) {
                values[method][name].push_back(value);
            }
        }
    }
    for (auto& [method, figures] : values) {
        for (auto& [name, list] : figures) {
            result.summary[method][name] = spreadOf(std::move(list));
        }
    }
}

} // namespace

Spread spreadOf(std::vector<double> values) {
    Spread spread;
    spread.count = values.size();
    if (values.empty()) {
        return spread;
    }
    std::sort(values.begin(), values.end());
    spread.median = quantile(values, 0.5);
    spread.q1 = quantile(values, 0.25);
    spread.q3 = quantile(values, 0.75);
    return spread;
}

std::map<std::string, std::map<std::string, double>>
comparisonFigures(const compare::Comparison& comparison) {
    std::map<std::string, std::map<std::string, double>> figures;
    for (const MethodResult& method : comparison.methods) {
        figures[method.method] = figuresOf(method, comparison);
    }
    return figures;
}

Result<ReproductionResult> runReproduction(const ReproductionSpec& spec, ProgressSink& progress,
                                           const CancelToken& cancel) {
    const auto start = std::chrono::steady_clock::now();
    auto family = blade::syntheticFamily(spec.seed, spec.blades);
    if (!family) {
        return std::unexpected(family.error());
    }
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    ReproductionResult result;
    result.spec = spec;
    for (std::size_t i = 0; i < family->size(); ++i) {
        const blade::FamilyMember& member = (*family)[i];
        progress.progress(static_cast<double>(i) / static_cast<double>(family->size()),
                          "comparing " + member.name);
        BladeFigures figures;
        figures.blade = member.name;
        auto comparison = compareMember(member, machine, spec.compare, cancel, figures);
        if (!comparison && comparison.error().code == ErrorCode::Cancelled) {
            return std::unexpected(comparison.error());
        }
        if (!comparison) {
            // One blade the method cannot handle is a finding of the study, not its end.
            figures.error = comparison.error().toString();
            progress.warning(member.name + ": " + figures.error);
        } else {
            figures.layers = comparison->reference.layers.size();
            figures.figures = comparisonFigures(*comparison);
            figures.missing = comparison->missingFigures();
        }
        result.blades.push_back(std::move(figures));
    }
    summarise(result);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::string reproductionJsonText(const ReproductionResult& result) {
    nlohmann::json json;
    json["seed"] = result.spec.seed;
    json["blades"] = result.spec.blades;
    for (const auto& [method, figures] : result.summary) {
        for (const auto& [name, spread] : figures) {
            json["summary"][method][name] = {{"median", spread.median},
                                             {"q1", spread.q1},
                                             {"q3", spread.q3},
                                             {"count", spread.count}};
        }
    }
    json["per_blade"] = nlohmann::json::array();
    for (const BladeFigures& blade : result.blades) {
        nlohmann::json entry{{"blade", blade.blade},
                             {"points", blade.points},
                             {"layers", blade.layers},
                             {"figures", blade.figures}};
        if (!blade.error.empty()) {
            entry["error"] = blade.error;
        }
        if (!blade.missing.empty()) {
            entry["missing_figures"] = blade.missing;
        }
        json["per_blade"].push_back(entry);
    }
    json["timing"] = {{"total_s", result.seconds}};
    return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string reproductionCsv(const ReproductionResult& result) {
    std::string csv = "blade,points,layers,method,figure,value\n";
    for (const BladeFigures& blade : result.blades) {
        for (const auto& [method, figures] : blade.figures) {
            for (const auto& [name, value] : figures) {
                csv += blade.blade + "," + std::to_string(blade.points) + "," +
                       std::to_string(blade.layers) + "," + method + "," + name + "," +
                       formatShortest(value) + "\n";
            }
        }
    }
    return csv;
}

std::string reproductionSummary(const ReproductionResult& result) {
    std::size_t failed = 0;
    for (const BladeFigures& blade : result.blades) {
        failed += blade.error.empty() ? 0 : 1;
    }
    std::string text = "reproduction " + std::to_string(result.blades.size()) +
                       " synthetic blades (seed " + std::to_string(result.spec.seed) + "), " +
                       std::to_string(failed) + " failed, " + formatFixed(result.seconds, 1) +
                       " s\n";
    for (const auto& [method, figures] : result.summary) {
        text += method + "\n";
        for (const auto& [name, spread] : figures) {
            std::string label = "  " + name;
            label.resize(std::max<std::size_t>(label.size() + 1, 48), ' ');
            text += label + "median " + formatFixed(spread.median, 3) + "  IQR [" +
                    formatFixed(spread.q1, 3) + ", " + formatFixed(spread.q3, 3) + "]  (" +
                    std::to_string(spread.count) + " blades)\n";
        }
    }
    for (const BladeFigures& blade : result.blades) {
        for (const std::string& reason : blade.missing) {
            text += "not computed  " + blade.blade + ": " + reason + "\n";
        }
        if (!blade.error.empty()) {
            text += "failed        " + blade.blade + ": " + blade.error + "\n";
        }
    }
    return text;
}

} // namespace bladeaxis::job

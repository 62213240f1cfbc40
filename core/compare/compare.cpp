#include "core/compare/compare.h"

#include "core/baselines/quaternion.h"
#include "core/optimal/layer_optimum.h"
#include "core/scheduling/plane_path.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace bladeaxis::compare {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

scheduling::ScheduleInput scheduleInputOf(const EvaluationContext& context) {
    scheduling::ScheduleInput input;
    input.toolRadius = context.toolRadius;
    input.centres = centresOf(context);
    for (const toolpath::ClRecord& record : context.pass) {
        input.axes.push_back(record.axis);
    }
    return input;
}

double layerStageSeconds(const scheduling::ScheduleResult& result) {
    double seconds = 0.0;
    for (const scheduling::LayerResult& layer : result.layers) {
        seconds += layer.seconds;
    }
    return seconds;
}

struct Scheduled {
    scheduling::ScheduleResult result;
    double seconds = 0.0;
};

Result<Scheduled> runEngine(const scheduling::ScheduleInput& input,
                            const scheduling::ScheduleParameters& parameters,
                            const CancelToken& cancel) {
    const auto start = Clock::now();
    auto result = scheduling::schedule(input, parameters, &cancel);
    if (!result) {
        return std::unexpected(result.error());
    }
    return Scheduled{std::move(*result), secondsSince(start)};
}

std::vector<Vec3> originalAxes(const EvaluationContext& context) {
    std::vector<Vec3> axes;
    axes.reserve(context.pass.size());
    for (const toolpath::ClRecord& record : context.pass) {
        axes.push_back(record.axis.normalized());
    }
    return axes;
}

} // namespace

std::vector<std::string> fairnessMetrics() {
    std::vector<std::string> metrics;
    for (const char* axis : {"X", "Y", "Z", "A"}) {
        metrics.push_back(std::string(axis) + " peak velocity");
        metrics.push_back(std::string(axis) + " peak acceleration");
    }
    metrics.insert(metrics.end(), {"T1", "T2"});
    return metrics;
}

double metricValue(const MethodResult& method, std::string_view metric) {
    if (metric == "T1") {
        return method.t1.time;
    }
    if (metric == "T2") {
        return method.t2.value_or(std::numeric_limits<double>::infinity());
    }
    kinematics::AxisId axis = kinematics::AxisId::A;
    for (kinematics::AxisId id : kinematics::kAllAxes) {
        if (metric.starts_with(kinematics::axisName(id))) {
            axis = id;
        }
    }
    const auto& series = method.profile.axis(axis);
    return metric.ends_with("velocity") ? series.peakVelocity : series.peakAcceleration;
}

std::optional<double> Comparison::bestQuaternion(std::string_view metric) const {
    for (const FairnessEntry& entry : quaternionFairness) {
        if (entry.metric == metric) {
            return entry.value;
        }
    }
    return std::nullopt;
}

const MethodResult* Comparison::find(std::string_view method) const {
    for (const MethodResult& result : methods) {
        if (result.method == method) {
            return &result;
        }
    }
    return nullptr;
}

std::vector<std::string> Comparison::missingFigures() const {
    std::vector<std::string> missing = optimumFailures;
    for (const MethodResult& method : methods) {
        if (!method.t2Failure.empty()) {
            missing.push_back(method.method + ": T2: " + method.t2Failure);
        }
    }
    return missing;
}

double reduction(double before, double after) {
    return before > 0.0 ? (before - after) / before : 0.0;
}

namespace {

// Every setting of the fairness rule, evaluated like the other methods; the `quaternion` row is
// the setting with the lowest peak A acceleration (the paper's headline metric), and each metric
// is compared against its own best setting (spec §7.2).
Status addQuaternion(const EvaluationContext& context, const scheduling::ScheduleInput& input,
                     const CompareOptions& options, const CancelToken& cancel,
                     Comparison& comparison) {
    auto settings = baselines::fairnessSettings();
    baselines::QuaternionSettings vector;
    vector.mode = baselines::QuaternionMode::Vector;
    settings.push_back(vector);
    for (baselines::QuaternionSettings& setting : settings) {
        setting.margin = options.best.marginRad;
        if (auto status = checkCancelled(cancel); !status) {
            return status;
        }
        const auto start = Clock::now();
        auto orientations = baselines::quaternionOrientations(input, comparison.reference, setting);
        const double seconds = secondsSince(start);
        if (!orientations) {
            comparison.quaternionFailures.push_back(baselines::describe(setting) + ": " +
                                                    orientations.error().message);
            continue;
        }
        auto evaluated = evaluateMethod(context, "quaternion", baselines::describe(setting),
                                        std::move(orientations->axes), seconds);
        if (!evaluated) {
            comparison.quaternionFailures.push_back(baselines::describe(setting) + ": " +
                                                    evaluated.error().message);
            continue;
        }
        if (!options.sweepFactors.empty()) {
            sweepRotaryLimits(context, options.sweepFactors, *evaluated);
        }
        comparison.quaternionSettings.push_back(std::move(*evaluated));
    }
    auto& variants = comparison.quaternionSettings;
    if (variants.empty()) {
        return {};
    }
    auto lowest = [&](std::string_view metric) {
        return std::min_element(variants.begin(), variants.end(),
                                [&](const MethodResult& a, const MethodResult& b) {
                                    return metricValue(a, metric) < metricValue(b, metric);
                                });
    };
    for (const std::string& metric : fairnessMetrics()) {
        const auto best = lowest(metric);
        comparison.quaternionFairness.push_back(
            {metric, best->setting, metricValue(*best, metric)});
    }
    comparison.methods.insert(comparison.methods.begin() + 1, *lowest("A peak acceleration"));
    return {};
}

// optimal-qp and optimal-lp (spec §9): the smoothest and the lowest-peak schedules in the same
// channel. A layer the solver cannot finish leaves the method out, with the reason (reported by
// compare.json, the batch summary, report.html and the reproduction).
template <class Add>
Status addOptimum(Add& add, Comparison& comparison) {
    const std::pair<const char*, optimal::Objective> methods[] = {
        {"optimal-qp", optimal::Objective::SmoothestQp},
        {"optimal-lp", optimal::Objective::MinimumPeakLp}};
    for (const auto& [name, objective] : methods) {
        auto optimum = optimal::optimalPath(comparison.reference, objective);
        if (!optimum) {
            comparison.optimumFailures.push_back(std::string(name) + ": " +
                                                 optimum.error().message);
            continue;
        }
        std::vector<Vec3> axes;
        for (double theta : optimum->thetaAbsolute) {
            axes.push_back(scheduling::axisFromPlaneAngle(theta, comparison.reference.tiltB0,
                                                          comparison.reference.traversalSign));
        }
        const char* setting = objective == optimal::Objective::SmoothestQp
                                  ? "minimum integral of theta''^2, interior point"
                                  : "minimum peak theta'', interior point";
        if (auto s = add(name, setting, std::move(axes), optimum->seconds); !s) {
            return s;
        }
        comparison.methods.back().layerStageSeconds = optimum->seconds;
    }
    return {};
}

} // namespace

Result<Comparison> compareMethods(EvaluationContext context, const CompareOptions& options,
                                  const CancelToken& cancel) {
    const scheduling::ScheduleInput input = scheduleInputOf(context);
    auto best =
        options.bestSchedule != nullptr
            ? Result<Scheduled>(Scheduled{*options.bestSchedule, options.bestScheduleSeconds})
            : runEngine(input, options.best, cancel);
    if (!best) {
        return std::unexpected(best.error());
    }
    auto faithful = runEngine(input, options.faithful, cancel);
    if (!faithful) {
        return std::unexpected(faithful.error());
    }
    Comparison comparison;
    if (context.machine != nullptr) {
        for (kinematics::AxisId axis : kinematics::kAllAxes) {
            comparison.letters[static_cast<std::size_t>(axis)] = context.machine->letter(axis);
        }
    }
    comparison.reference = std::move(best->result);
    context.reference = &comparison.reference;

    auto add = [&](std::string method, std::string setting, std::vector<Vec3> axes,
                   double seconds) -> Status {
        if (auto status = checkCancelled(cancel); !status) {
            return status;
        }
        auto evaluated = evaluateMethod(context, std::move(method), std::move(setting),
                                        std::move(axes), seconds);
        if (!evaluated) {
            return std::unexpected(evaluated.error());
        }
        if (!options.sweepFactors.empty()) {
            sweepRotaryLimits(context, options.sweepFactors, *evaluated);
        }
        comparison.methods.push_back(std::move(*evaluated));
        return {};
    };
    if (auto s = add("original", "as read", originalAxes(context), 0.0); !s) {
        return std::unexpected(s.error());
    }
    if (auto s = add("stheta-faithful", "paper epsilon rule, fixed lead fraction",
                     faithful->result.newAxes, faithful->seconds);
        !s) {
        return std::unexpected(s.error());
    }
    comparison.methods.back().layerStageSeconds = layerStageSeconds(faithful->result);
    if (auto s = add("stheta-best", "exact epsilon, auto lead fraction",
                     comparison.reference.newAxes, best->seconds);
        !s) {
        return std::unexpected(s.error());
    }
    comparison.methods.back().layerStageSeconds = layerStageSeconds(comparison.reference);
    if (auto s = addQuaternion(context, input, options, cancel, comparison); !s) {
        return std::unexpected(s.error());
    }
    if (options.optimum) {
        if (auto s = addOptimum(add, comparison); !s) {
            return std::unexpected(s.error());
        }
    }
    return comparison;
}

} // namespace bladeaxis::compare

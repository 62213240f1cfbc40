#include "core/compare/compare.h"

#include <chrono>

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

const MethodResult* Comparison::find(std::string_view method) const {
    for (const MethodResult& result : methods) {
        if (result.method == method) {
            return &result;
        }
    }
    return nullptr;
}

std::vector<double> defaultSweepFactors() {
    return {0.5, 0.75, 1.0, 1.5, 2.0};
}

double reduction(double before, double after) {
    return before > 0.0 ? (before - after) / before : 0.0;
}

Result<Comparison> compareMethods(EvaluationContext context, const CompareOptions& options,
                                  const CancelToken& cancel) {
    const scheduling::ScheduleInput input = scheduleInputOf(context);
    auto best = runEngine(input, options.best, cancel);
    if (!best) {
        return std::unexpected(best.error());
    }
    auto faithful = runEngine(input, options.faithful, cancel);
    if (!faithful) {
        return std::unexpected(faithful.error());
    }
    Comparison comparison;
    comparison.reference = std::move(best->result);
    context.reference = &comparison.reference;

    auto add = [&](std::string method, std::string setting, std::vector<Vec3> axes,
                   double seconds) -> Status {
        if (cancel.isCancelled()) {
            return makeError(ErrorCode::Cancelled, "comparison cancelled");
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
    if (auto s = add("stheta-best", "exact epsilon, auto lead fraction",
                     comparison.reference.newAxes, best->seconds);
        !s) {
        return std::unexpected(s.error());
    }
    return comparison;
}

} // namespace bladeaxis::compare

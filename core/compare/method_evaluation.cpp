#include "core/compare/method_evaluation.h"

#include "core/analysis/time_optimal.h"
#include "core/analysis/time_optimal_sweep.h"
#include "core/kinematics/kinematics.h"

namespace bladeaxis::compare {

std::vector<Vec3> centresOf(const EvaluationContext& context) {
    std::vector<Vec3> centres;
    centres.reserve(context.pass.size());
    for (const toolpath::ClRecord& record : context.pass) {
        centres.push_back(toolpath::ballCentre(record, context.toolRadius));
    }
    return centres;
}

namespace {

Status validate(const EvaluationContext& context, const std::vector<Vec3>& toolAxes) {
    if (context.machine == nullptr || context.reference == nullptr ||
        context.originalAxes.size() != context.pass.size() || context.pass.empty()) {
        return makeError(ErrorCode::InvalidArgument, "incomplete evaluation context");
    }
    if (toolAxes.size() != context.pass.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "expected " + std::to_string(context.pass.size()) + " tool axes, got " +
                             std::to_string(toolAxes.size()));
    }
    return {};
}

} // namespace

Result<MethodResult> evaluateMethod(const EvaluationContext& context, std::string method,
                                    std::string setting, std::vector<Vec3> toolAxes,
                                    double computeSeconds) {
    if (auto status = validate(context, toolAxes); !status) {
        return std::unexpected(status.error());
    }
    const std::vector<Vec3> centres = centresOf(context);
    std::vector<toolpath::ClRecord> records(context.pass.begin(), context.pass.end());
    std::vector<kinematics::ToolPose> poses;
    poses.reserve(records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
        records[i].axis = toolAxes[i].normalized();
        records[i].tip = centres[i] - context.toolRadius * records[i].axis;
        records[i].axes.reset();
        poses.push_back({records[i].tip, records[i].axis});
    }
    auto solved = kinematics::inverseKinematicsAlong(context.machine->chain, poses,
                                                     context.originalAxes.front().a);
    if (solved.failedIndex) {
        Error error = solved.failure;
        error.message = method + ": " + error.message;
        error.where.line = context.pass[*solved.failedIndex].line;
        return std::unexpected(error);
    }
    auto machineAxes =
        std::make_shared<const std::vector<kinematics::MachineAxes>>(std::move(solved.axes));
    auto profile = analysis::analyseAxisMotion(machineAxes, {.records = records}, context.analysis);
    if (!profile) {
        return std::unexpected(profile.error());
    }
    MethodResult result;
    result.method = std::move(method);
    result.setting = std::move(setting);
    result.channel = measureInChannel(*context.reference, toolAxes);
    result.toolAxes = std::move(toolAxes);
    result.machineAxes = std::move(machineAxes);
    result.profile = std::move(*profile);
    result.t1 = analysis::constantFeedTime(result.profile, *context.machine, false);
    result.blockByBlock =
        analysis::blockByBlockTime(*result.machineAxes, {.records = records}, *context.machine);
    if (auto t2 = analysis::convergedTimeOptimal(result.profile, *context.machine)) {
        result.t2 = t2->time;
    } else {
        result.t2Failure = t2.error().message;
    }
    if (auto t2j = analysis::timeOptimalTime(result.profile, *context.machine,
                                             {.jerkHeuristic = true, .maxJerkRounds = 20})) {
        result.t2Jerk = t2j->time;
    }
    result.computeSeconds = computeSeconds;
    return result;
}

void sweepRotaryLimits(const EvaluationContext& context, std::span<const double> factors,
                       MethodResult& result) {
    result.sweep.clear();
    for (double factor : factors) {
        const kinematics::MachineModel machine =
            analysis::scaledRotaryLimits(*context.machine, factor);
        result.sweep.push_back({factor,
                                analysis::constantFeedTime(result.profile, machine, false).time,
                                analysis::timeOptimalSeconds(result.profile, machine)});
    }
}

} // namespace bladeaxis::compare

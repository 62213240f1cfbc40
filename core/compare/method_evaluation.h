#pragma once
// One method's tool orientations, evaluated exactly like every other method's (spec §8.5): same
// ball centres, new tips O = Q - R V, IK with A continuous from the original start, the same
// axis analysis at the same constant feed, the same machine limits.

#include "core/analysis/axis_profile.h"
#include "core/analysis/constant_feed.h"
#include "core/base/error.h"
#include "core/compare/channel_metrics.h"
#include "core/kinematics/machine_model.h"
#include "core/toolpath/toolpath.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::compare {

struct EvaluationContext {
    std::span<const toolpath::ClRecord> pass;              // the original cutting pass
    std::span<const kinematics::MachineAxes> originalAxes; // per pass record
    double toolRadius = 0.0;                               // mm
    const kinematics::MachineModel* machine = nullptr;
    analysis::AxisProfileOptions analysis;
    const scheduling::ScheduleResult* reference = nullptr; // the layers and channel of the engine
};

struct MethodResult {
    std::string method;  // original | quaternion | stheta-faithful | stheta-best | optimal-qp | ...
    std::string setting; // the variant or parameters used, for the report
    std::vector<Vec3> toolAxes;                       // per pass record, unit
    std::vector<kinematics::MachineAxes> machineAxes; // per pass record, A continuous
    analysis::AxisProfile profile;
    analysis::ConstantFeedTime t1;
    std::optional<double> t2; // s, time-optimal under the machine limits, when computed
    ChannelMetrics channel;
    double computeSeconds = 0.0; // wall time of the method itself (not of its evaluation)
};

// Ball centres of the pass, Q = O + R V.
std::vector<Vec3> centresOf(const EvaluationContext& context);

Result<MethodResult> evaluateMethod(const EvaluationContext& context, std::string method,
                                    std::string setting, std::vector<Vec3> toolAxes,
                                    double computeSeconds);

} // namespace bladeaxis::compare

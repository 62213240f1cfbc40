#pragma once
// One method's tool orientations, evaluated exactly like every other method's (spec §8.5): same
// ball centres, new tips O = Q - R V, IK with A continuous from the original start, the same
// axis analysis at the same constant feed, the same machine limits.

#include "core/analysis/axis_profile.h"
#include "core/analysis/block_planner.h"
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

// Machining time with the rotary axis's velocity, acceleration and jerk limits scaled by
// `factor` (spec §8.3: the ranking of methods depends on which axis binds).
struct LimitSweepPoint {
    double factor = 1.0;
    double t1 = 0.0;          // s
    std::optional<double> t2; // s, when the time-optimal model is computed
};

struct MethodResult {
    std::string method;  // original | quaternion | stheta-faithful | stheta-best | optimal-qp | ...
    std::string setting; // the variant or parameters used, for the report
    std::vector<Vec3> toolAxes; // per pass record, unit
    // Per pass record, A continuous; shared with the profile, which reads its positions there.
    analysis::SharedMachineAxes machineAxes;
    analysis::AxisProfile profile;
    analysis::ConstantFeedTime t1;
    std::optional<double> t2;     // s, time-optimal under the machine limits, when computed
    std::string t2Failure;        // why t2 is missing, when it is
    std::optional<double> t2Jerk; // s, T2 with the jerk heuristic (spec §8.3 "T2+J")
    // The block-by-block controller model (LinuxCNC 2.9's planner on rotary blocks).
    analysis::BlockPlannerTime blockByBlock;
    ChannelMetrics channel;
    std::vector<LimitSweepPoint> sweep; // empty unless requested
    double computeSeconds = 0.0;        // wall time of the method itself (not of its evaluation)
    // Spec §8.5 "wall time per layer": the per-layer stage alone, summed over the layers (the
    // engine's layers after its channel stage, or the optimum's solves, which start from the
    // engine's bounds), so that both sides exclude the shared path preparation. 0 when the
    // method has no layers.
    double layerStageSeconds = 0.0;
};

// T1 (and T2 when the result has one) for each factor.
void sweepRotaryLimits(const EvaluationContext& context, std::span<const double> factors,
                       MethodResult& result);

// Ball centres of the pass, Q = O + R V.
std::vector<Vec3> centresOf(const EvaluationContext& context);

Result<MethodResult> evaluateMethod(const EvaluationContext& context, std::string method,
                                    std::string setting, std::vector<Vec3> toolAxes,
                                    double computeSeconds);

} // namespace bladeaxis::compare

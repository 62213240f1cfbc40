#pragma once
// Forward and inverse kinematics of the table-A / head-B chain (spec §6.3), as pure functions.
// Branch selection: A is chosen nearest to a reference angle (unwrapping), B in [-90, 90] deg.

#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/geometry/vec.h"
#include "core/kinematics/machine_model.h"

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace bladeaxis::kinematics {

// Tool tip O and unit tool axis V (tip -> spindle) in the workpiece frame W, mm.
struct ToolPose {
    Vec3 tip = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();
};

ToolPose forwardKinematics(const TableAHeadB& chain, const MachineAxes& axes);

// Inverse kinematics. `aReference` (rad, programmed convention) selects the A branch: the
// result is the solution nearest to it, so a sequence of calls unwraps A continuously.
// Errors (Geometry): non-finite input, zero axis, or an axis along the A axis (A undefined).
Result<MachineAxes> inverseKinematics(const TableAHeadB& chain, const ToolPose& pose,
                                      double aReference = 0.0);

// IK of consecutive poses with A continuous: the first pose is solved nearest `aStart`, every
// later one nearest the A of the one before. A failed pose (the first one) is reported as
// `failedIndex`, with no axes. The poses are solved on the context's threads
// (core/base/execution.h); only the unwrapping runs in order, so the result is the one-thread
// result bit for bit.
struct IkAlongResult {
    std::vector<MachineAxes> axes;
    std::optional<std::size_t> failedIndex;
    Error failure; // meaningful when failedIndex is set
};
IkAlongResult inverseKinematicsAlong(const TableAHeadB& chain, std::span<const ToolPose> poses,
                                     double aStart);
// The same for `count` poses made on demand: poseAt(i) is called (from the context's threads,
// twice per pose) instead of a pose array being kept, 48 bytes per pose. With a token, each
// thread looks at it every 65,536 poses (a few milliseconds): once it is set the result is
// cancelledError() (progress.h).
Result<IkAlongResult> inverseKinematicsAlong(const TableAHeadB& chain, std::size_t count,
                                             const std::function<ToolPose(std::size_t)>& poseAt,
                                             double aStart, const CancelToken* cancel = nullptr);

// Tool axis for a given programmed A and B, in W (spec §6.1 with the sign conventions).
Vec3 toolAxisFor(const TableAHeadB& chain, double a, double b);

} // namespace bladeaxis::kinematics

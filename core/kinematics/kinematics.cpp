#include "core/kinematics/kinematics.h"

#include "core/base/parallel.h"
#include "core/geometry/angles.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::kinematics {

namespace {

// Direction of the spindle in machine coordinates for a mathematical tilt angle.
Vec3 spindleDirection(double bMath) {
    return {std::sin(bMath), 0.0, std::cos(bMath)};
}

// The mathematical tilt and the wrapped table angle of a tool axis: the part of the inverse
// kinematics that needs no neighbour, so a whole path can be solved on several threads.
struct AxisAngles {
    double bMath = 0.0;
    double aMathWrapped = 0.0;
};

Result<AxisAngles> axisAngles(const ToolPose& pose) {
    if (!pose.tip.allFinite() || !pose.axis.allFinite()) {
        return makeError(ErrorCode::Geometry, "tool pose is not finite (NaN or infinity)");
    }
    const double length = pose.axis.norm();
    if (length < 1e-12) {
        return makeError(ErrorCode::Geometry, "tool axis has zero length");
    }
    const Vec3 v = pose.axis / length;
    const double inPlane = std::hypot(v.y(), v.z());
    if (inPlane < 1e-9) {
        return makeError(ErrorCode::Geometry,
                         "tool axis is parallel to the A axis: A is undefined (B would be 90 deg)");
    }
    return AxisAngles{std::asin(std::clamp(v.x(), -1.0, 1.0)), std::atan2(v.y(), v.z())};
}

// The programmed axes once the table angle is unwrapped (aMath on the chosen branch).
MachineAxes axesAt(const TableAHeadB& chain, const ToolPose& pose, double bMath, double aMath) {
    const Vec3 tipMachine = rotationX(aMath) * pose.tip + chain.tableOffset;
    const Vec3 programmed =
        chain.tipInWorkpiece
            ? pose.tip
            : Vec3(tipMachine + chain.pivotLength * spindleDirection(bMath) + chain.headOffset);
    MachineAxes axes;
    axes.x = programmed.x();
    axes.y = programmed.y();
    axes.z = programmed.z();
    axes.a = chain.aSign * aMath;
    axes.b = chain.bSign * bMath;
    return axes;
}

} // namespace

IkAlongResult inverseKinematicsAlong(const TableAHeadB& chain, std::span<const ToolPose> poses,
                                     double aStart) {
    // Without a token nothing cancels it: the result is always there.
    return *inverseKinematicsAlong(
        chain, poses.size(), [poses](std::size_t i) { return poses[i]; }, aStart);
}

Result<IkAlongResult> inverseKinematicsAlong(const TableAHeadB& chain, std::size_t count,
                                             const std::function<ToolPose(std::size_t)>& poseAt,
                                             double aStart, const CancelToken* cancel) {
    IkAlongResult result;
    // The angles of every pose at once (they need no neighbour), the earliest failure wins.
    // They wait in the result's own a and b (math convention, A wrapped) until the axes are
    // made, rather than in an array of their own. A poll that finds the token set stops the
    // pass like a failure; the token, looked at afterwards, tells the two apart.
    result.axes.resize(count);
    const std::size_t failed = forEachUntilFirstFailure(count, [&](std::size_t i) {
        if (isCancelledAt(cancel, i)) {
            return false;
        }
        auto solved = axisAngles(poseAt(i));
        if (solved) {
            result.axes[i].b = solved->bMath;
            result.axes[i].a = solved->aMathWrapped;
        }
        return solved.has_value();
    });
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    if (failed < count) {
        result.axes.clear();
        result.failedIndex = failed;
        result.failure = axisAngles(poseAt(failed)).error();
        return result;
    }
    // A continuous: each angle on the branch nearest the previous one, in order.
    double reference = chain.aSign * aStart;
    for (MachineAxes& axes : result.axes) {
        axes.a = geometry::unwrapNear(axes.a, reference);
        reference = axes.a;
    }
    forEachRange(count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            if (isCancelledAt(cancel, i)) {
                return;
            }
            const double bMath = result.axes[i].b;
            const double aMath = result.axes[i].a;
            result.axes[i] = axesAt(chain, poseAt(i), bMath, aMath);
        }
    });
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    return result;
}

Vec3 toolAxisFor(const TableAHeadB& chain, double a, double b) {
    const double aMath = chain.aSign * a;
    const double bMath = chain.bSign * b;
    return rotationX(-aMath) * spindleDirection(bMath);
}

ToolPose forwardKinematics(const TableAHeadB& chain, const MachineAxes& axes) {
    const double aMath = chain.aSign * axes.a;
    const double bMath = chain.bSign * axes.b;
    const Vec3 spindle = spindleDirection(bMath);
    const Vec3 programmed(axes.x, axes.y, axes.z);
    const Mat3 toWorkpiece = rotationX(-aMath);
    if (chain.tipInWorkpiece) {
        return {programmed, toWorkpiece * spindle};
    }
    const Vec3 tipMachine = programmed - chain.pivotLength * spindle - chain.headOffset;
    return {toWorkpiece * (tipMachine - chain.tableOffset), toWorkpiece * spindle};
}

Result<MachineAxes> inverseKinematics(const TableAHeadB& chain, const ToolPose& pose,
                                      double aReference) {
    auto angles = axisAngles(pose);
    if (!angles) {
        return std::unexpected(angles.error());
    }
    const double aMath = geometry::unwrapNear(angles->aMathWrapped, chain.aSign * aReference);
    return axesAt(chain, pose, angles->bMath, aMath);
}

} // namespace bladeaxis::kinematics

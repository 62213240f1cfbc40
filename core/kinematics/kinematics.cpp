#include "core/kinematics/kinematics.h"

#include "core/geometry/angles.h"

#include <cmath>

namespace bladeaxis::kinematics {

namespace {

// Direction of the spindle in machine coordinates for a mathematical tilt angle.
Vec3 spindleDirection(double bMath) {
    return {std::sin(bMath), 0.0, std::cos(bMath)};
}

} // namespace

IkAlongResult inverseKinematicsAlong(const TableAHeadB& chain, std::span<const ToolPose> poses,
                                     double aStart) {
    IkAlongResult result;
    result.axes.reserve(poses.size());
    double reference = aStart;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        auto axes = inverseKinematics(chain, poses[i], reference);
        if (!axes) {
            result.failedIndex = i;
            result.failure = axes.error();
            return result;
        }
        result.axes.push_back(*axes);
        reference = axes->a;
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
    const double bMath = std::asin(std::clamp(v.x(), -1.0, 1.0));
    const double aMathRaw = std::atan2(v.y(), v.z());
    const double aMath = geometry::unwrapNear(aMathRaw, chain.aSign * aReference);

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

} // namespace bladeaxis::kinematics

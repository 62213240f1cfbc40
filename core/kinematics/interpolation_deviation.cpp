#include "core/kinematics/interpolation_deviation.h"

#include "core/kinematics/kinematics.h"

#include <algorithm>

namespace bladeaxis::kinematics {

namespace {

MachineAxes lerp(const MachineAxes& from, const MachineAxes& to, double t) {
    MachineAxes axes;
    for (const AxisId axis : kAllAxes) {
        axes[axis] = from[axis] + t * (to[axis] - from[axis]);
    }
    return axes;
}

Vec3 ballCentreAt(const TableAHeadB& chain, const MachineAxes& axes, double radius) {
    const ToolPose pose = forwardKinematics(chain, axes);
    return pose.tip + radius * pose.axis;
}

double distanceToSegment(const Vec3& point, const Vec3& from, const Vec3& to) {
    const Vec3 chord = to - from;
    const double length2 = chord.squaredNorm();
    const double t =
        length2 > 0.0 ? std::clamp((point - from).dot(chord) / length2, 0.0, 1.0) : 0.0;
    return (point - (from + t * chord)).norm();
}

} // namespace

InterpolationDeviation interpolationDeviation(std::span<const MachineAxes> axes,
                                              const TableAHeadB& chain, double ballRadius,
                                              int samplesPerBlock) {
    InterpolationDeviation result;
    if (axes.size() < 2) {
        return result;
    }
    Vec3 start = ballCentreAt(chain, axes[0], ballRadius);
    for (std::size_t i = 1; i < axes.size(); ++i) {
        const Vec3 end = ballCentreAt(chain, axes[i], ballRadius);
        for (int k = 1; k <= samplesPerBlock; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(samplesPerBlock + 1);
            const Vec3 centre = ballCentreAt(chain, lerp(axes[i - 1], axes[i], t), ballRadius);
            const double deviation = distanceToSegment(centre, start, end);
            if (deviation > result.maxMm) {
                result.maxMm = deviation;
                result.block = i;
            }
        }
        start = end;
    }
    result.blocks = axes.size() - 1;
    return result;
}

} // namespace bladeaxis::kinematics

#include "core/kinematics/interpolation_deviation.h"

#include "core/base/parallel.h"
#include "core/kinematics/kinematics.h"

#include <algorithm>
#include <vector>

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

namespace {

// The largest deviation of blocks [begin, end) (block i ends at record i), the first block where
// it occurs; stops with what it has once `cancel` is set (looked at every
// kIterationsPerCancelPoll blocks).
InterpolationDeviation deviationOfBlocks(std::span<const MachineAxes> axes,
                                         const TableAHeadB& chain, double ballRadius,
                                         int samplesPerBlock, std::size_t begin, std::size_t end,
                                         const CancelToken* cancel) {
    InterpolationDeviation result;
    Vec3 start = ballCentreAt(chain, axes[begin - 1], ballRadius);
    for (std::size_t i = begin; i < end; ++i) {
        if (isCancelledAt(cancel, i - begin + 1)) {
            return result;
        }
        const Vec3 finish = ballCentreAt(chain, axes[i], ballRadius);
        for (int k = 1; k <= samplesPerBlock; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(samplesPerBlock + 1);
            const Vec3 centre = ballCentreAt(chain, lerp(axes[i - 1], axes[i], t), ballRadius);
            const double deviation = distanceToSegment(centre, start, finish);
            if (deviation > result.maxMm) {
                result.maxMm = deviation;
                result.block = i;
            }
        }
        start = finish;
    }
    return result;
}

} // namespace

// The blocks are measured in ranges on the context's threads; each range starts from the
// centre its first block starts at (the same bits the serial loop had there), and the ranges'
// maxima are combined in order, strictly greater winning, so the first block with the largest
// deviation is the serial loop's.
InterpolationDeviation interpolationDeviation(std::span<const MachineAxes> axes,
                                              const TableAHeadB& chain, double ballRadius,
                                              int samplesPerBlock, const CancelToken* cancel) {
    InterpolationDeviation result;
    if (axes.size() < 2) {
        return result;
    }
    const std::size_t blocks = axes.size() - 1;
    std::vector<InterpolationDeviation> ranges(rangeCount(blocks));
    forEachRangeOf(blocks, ranges.size(),
                   [&](std::size_t range, std::size_t begin, std::size_t end) {
                       ranges[range] = deviationOfBlocks(axes, chain, ballRadius, samplesPerBlock,
                                                         begin + 1, end + 1, cancel);
                   });
    for (const InterpolationDeviation& range : ranges) {
        if (range.maxMm > result.maxMm) {
            result.maxMm = range.maxMm;
            result.block = range.block;
        }
    }
    result.blocks = blocks;
    return result;
}

} // namespace bladeaxis::kinematics

#include "core/analysis/block_planner.h"

#include "core/base/units.h"
#include "core/geometry/vec.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace bladeaxis::analysis {

namespace {

using kinematics::AxisId;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// LinuxCNC drops an axis's displacement below this (mm or degrees) when it plans a move.
constexpr double kTinyDisplacement = 1e-7;
// The share of a block's acceleration its planner uses while it may blend with a neighbour.
constexpr double kParabolicBlendShare = 0.5;

bool limited(double limit) {
    return std::isfinite(limit) && limit > 0.0;
}

// One planned move: its length, speed and acceleration limits and its XYZ direction.
struct PlannedBlock {
    double length = 0.0;       // mm (degrees for a purely rotary move)
    double velocity = 0.0;     // the most the block may reach
    double acceleration = 0.0; // the planner's share of the block's acceleration limit
    bool rotary = false;

    double peakVelocity() const { return std::min(velocity, std::sqrt(acceleration * length)); }
    // From rest to rest: a trapezoid, or a triangle when the block is too short for v.
    double duration() const {
        const double peak = peakVelocity();
        if (peak < velocity) {
            return 2.0 * peak / acceleration;
        }
        return length / velocity + velocity / acceleration;
    }
};

// An axis's displacement in LinuxCNC's units (mm, degrees) and its limits in the same units.
struct AxisMove {
    double displacement = 0.0, velocity = kInfinity, acceleration = kInfinity;
};

std::array<AxisMove, 5> axisMoves(const kinematics::MachineAxes& from,
                                  const kinematics::MachineAxes& to,
                                  const kinematics::MachineModel& machine) {
    std::array<AxisMove, 5> moves{};
    for (const AxisId axis : kinematics::kAllAxes) {
        const double scale = kinematics::isRotary(axis) ? units::radToDeg(1.0) : 1.0;
        const auto& limits = machine.limit(axis);
        AxisMove& move = moves[static_cast<int>(axis)];
        move.displacement = std::abs(to[axis] - from[axis]) * scale;
        if (move.displacement < kTinyDisplacement) {
            move.displacement = 0.0;
        }
        move.velocity = limited(limits.velocity) ? limits.velocity * scale : kInfinity;
        move.acceleration = limited(limits.acceleration) ? limits.acceleration * scale : kInfinity;
    }
    return moves;
}

// LinuxCNC's canonical layer: the move's length is its XYZ length (the rotary length when no
// linear axis moves), and each limit is the length over the longest time any axis needs.
PlannedBlock planBlock(const kinematics::MachineAxes& from, const kinematics::MachineAxes& to,
                       double feed, const kinematics::MachineModel& machine) {
    const auto moves = axisMoves(from, to, machine);
    PlannedBlock block;
    const Vec3 linear(moves[0].displacement, moves[1].displacement, moves[2].displacement);
    const double rotary = std::hypot(moves[3].displacement, moves[4].displacement);
    block.rotary = rotary > 0.0;
    block.length = linear.norm() > 0.0 ? linear.norm() : rotary;
    double velocityTime = 0.0, accelerationTime = 0.0;
    for (const AxisMove& move : moves) {
        velocityTime = std::max(velocityTime, move.displacement / move.velocity);
        accelerationTime = std::max(accelerationTime, move.displacement / move.acceleration);
    }
    block.velocity = feed > 0.0 ? feed : kInfinity;
    if (velocityTime > 0.0) {
        block.velocity = std::min(block.velocity, block.length / velocityTime);
    }
    const double acceleration =
        accelerationTime > 0.0 ? block.length / accelerationTime : kInfinity;
    block.acceleration = kParabolicBlendShare * acceleration;
    return block;
}

// The velocity below which the planner starts the next block while this one decelerates
// (LinuxCNC's tpComputeBlendVelocity): the blend may take at most half of either block.
double blendVelocity(const PlannedBlock& current, const PlannedBlock& next) {
    const double reachable = current.peakVelocity(), reachableNext = next.peakVelocity();
    const double longestBlend = std::min(current.length / reachable, next.length / reachableNext);
    const double blendAtFullAcceleration =
        std::max(reachable / current.acceleration, reachableNext / next.acceleration);
    return std::min(reachable,
                    std::min(longestBlend, blendAtFullAcceleration) * current.acceleration);
}

bool plannable(const PlannedBlock& block) {
    return block.length > 0.0 && std::isfinite(block.velocity) && block.velocity > 0.0 &&
           block.acceleration > 0.0;
}

} // namespace

namespace {

// The planner's time of consecutive records, the feed of the move ending at record i being
// feedOf(i). Only a block and the next plannable one are held: the blend reads no further.
template <class FeedOf>
BlockPlannerTime planAlong(std::span<const kinematics::MachineAxes> axes, const FeedOf& feedOf,
                           const kinematics::MachineModel& machine) {
    BlockPlannerTime result;
    std::optional<PlannedBlock> previous;
    const auto add = [&result](const PlannedBlock& block, const PlannedBlock* next) {
        if (!std::isfinite(block.acceleration)) { // no axis limits it: it runs at F
            result.time += block.length / block.velocity;
        } else {
            result.time += block.duration();
            if (next != nullptr && std::isfinite(next->acceleration)) {
                result.time -= std::min(blendVelocity(block, *next), block.peakVelocity()) /
                               block.acceleration;
            }
        }
        result.rotaryBlocks += block.rotary ? 1 : 0;
        ++result.blocks;
    };
    for (std::size_t i = 1; i < axes.size(); ++i) {
        const PlannedBlock block = planBlock(axes[i - 1], axes[i], feedOf(i), machine);
        if (!plannable(block)) {
            continue;
        }
        if (previous) {
            add(*previous, &block);
        }
        previous = block;
    }
    if (previous) {
        add(*previous, nullptr);
    }
    result.meanBlockSeconds =
        result.blocks > 0 ? result.time / static_cast<double>(result.blocks) : 0.0;
    return result;
}

} // namespace

BlockPlannerTime blockByBlockTime(std::span<const kinematics::MachineAxes> axes,
                                  std::span<const double> feeds,
                                  const kinematics::MachineModel& machine) {
    if (feeds.size() != axes.size()) {
        return {};
    }
    return planAlong(
        axes, [feeds](std::size_t i) { return feeds[i]; }, machine);
}

BlockPlannerTime blockByBlockTime(std::span<const kinematics::MachineAxes> axes,
                                  const PathSamples& path,
                                  const kinematics::MachineModel& machine) {
    if (path.size() != axes.size()) {
        return {};
    }
    return planAlong(
        axes, [&path](std::size_t i) { return path.feed(i); }, machine);
}

} // namespace bladeaxis::analysis

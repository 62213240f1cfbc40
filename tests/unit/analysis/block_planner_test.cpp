// The block-by-block cycle-time model (LinuxCNC 2.9's planner on rotary blocks) against cases
// worked by hand from its rules: each block from rest to rest at half its acceleration limit,
// the next one starting as this one decelerates below the blend velocity.

#include "core/analysis/block_planner.h"
#include "core/base/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bladeaxis::analysis {
namespace {

using kinematics::AxisId;
using kinematics::MachineAxes;

kinematics::MachineModel machineWith(double linearVelocity, double linearAcceleration,
                                     double rotaryVelocityDeg, double rotaryAccelerationDeg) {
    kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    for (const AxisId axis : kinematics::kAllAxes) {
        auto& limits = machine.limit(axis);
        const bool rotary = kinematics::isRotary(axis);
        limits.velocity = rotary ? units::degToRad(rotaryVelocityDeg) : linearVelocity;
        limits.acceleration = rotary ? units::degToRad(rotaryAccelerationDeg) : linearAcceleration;
    }
    return machine;
}

// `blocks` equal moves of `step` mm along X, with A turning `aStepDeg` per block.
std::vector<MachineAxes> straightRun(std::size_t blocks, double step, double aStepDeg = 0.0) {
    std::vector<MachineAxes> axes;
    for (std::size_t i = 0; i <= blocks; ++i) {
        const double k = static_cast<double>(i);
        axes.push_back({k * step, 0.0, 0.0, units::degToRad(k * aStepDeg), 0.0});
    }
    return axes;
}

TEST(BlockPlanner, ALongBlockIsATrapezoidAtHalfItsAcceleration) {
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const auto axes = straightRun(1, 100.0);
    const std::vector<double> feeds(axes.size(), 50.0);
    const BlockPlannerTime result = blockByBlockTime(axes, feeds, machine);
    const double a = 0.5 * 3000.0;
    EXPECT_NEAR(result.time, 100.0 / 50.0 + 50.0 / a, 1e-12);
    EXPECT_EQ(result.blocks, 1U);
    EXPECT_EQ(result.rotaryBlocks, 0U);
}

TEST(BlockPlanner, ShortEqualBlocksTakeSqrtTwoLOverAEach) {
    // Triangles that overlap by their deceleration: (N + 1) sqrt(L / a'), a' = a / 2.
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const std::size_t n = 200;
    const double step = 0.2;
    const auto axes = straightRun(n, step);
    const std::vector<double> feeds(axes.size(), 50.0);
    const BlockPlannerTime result = blockByBlockTime(axes, feeds, machine);
    const double perBlock = std::sqrt(2.0 * step / 3000.0);
    EXPECT_NEAR(result.time, static_cast<double>(n + 1) * perBlock, 1e-9);
}

TEST(BlockPlanner, TheRotaryStepSetsTheTimeWhenItNeedsLongerThanTheLinearMove) {
    // 0.2 mm of X at 3000 mm/s^2 needs 0.2 / 3000 s^2; 1 deg of A at 1800 deg/s^2 needs
    // 1 / 1800: A binds and a block lasts sqrt(2 dA / aA).
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const std::size_t n = 100;
    const auto axes = straightRun(n, 0.2, 1.0);
    const std::vector<double> feeds(axes.size(), 50.0);
    const BlockPlannerTime result = blockByBlockTime(axes, feeds, machine);
    EXPECT_NEAR(result.time, static_cast<double>(n + 1) * std::sqrt(2.0 / 1800.0), 1e-9);
    EXPECT_EQ(result.rotaryBlocks, n);
}

TEST(BlockPlanner, APurelyRotaryMoveIsMeasuredInDegreesAtTheFeedAsDegreesPerMinute) {
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const std::vector<MachineAxes> axes{{0, 0, 0, 0, 0}, {0, 0, 0, units::degToRad(90.0), 0}};
    const std::vector<double> feeds{10.0, 10.0}; // F600: 10 deg/s
    const BlockPlannerTime result = blockByBlockTime(axes, feeds, machine);
    EXPECT_NEAR(result.time, 90.0 / 10.0 + 10.0 / 900.0, 1e-9);
}

TEST(BlockPlanner, ZeroLengthMovesAreSkipped) {
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    std::vector<MachineAxes> axes = straightRun(3, 1.0);
    axes.insert(axes.begin() + 2, axes[1]);
    const std::vector<double> feeds(axes.size(), 50.0);
    EXPECT_EQ(blockByBlockTime(axes, feeds, machine).blocks, 3U);
}

TEST(BlockPlanner, FewerLongerBlocksOverTheSamePathAreFaster) {
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const auto fine = straightRun(100, 0.2, 1.0);
    const auto coarse = straightRun(50, 0.4, 2.0);
    EXPECT_LT(blockByBlockTime(coarse, std::vector<double>(coarse.size(), 50.0), machine).time,
              blockByBlockTime(fine, std::vector<double>(fine.size(), 50.0), machine).time);
}

TEST(BlockPlanner, HigherLimitsNeverMakeItSlower) {
    const auto axes = straightRun(50, 0.3, 1.5);
    const std::vector<double> feeds(axes.size(), 50.0);
    const double slow = blockByBlockTime(axes, feeds, machineWith(500, 3000, 360, 1800)).time;
    const double fast = blockByBlockTime(axes, feeds, machineWith(500, 6000, 360, 3600)).time;
    EXPECT_LE(fast, slow);
}

TEST(BlockPlanner, FewerThanTwoRecordsGiveNoTime) {
    const auto machine = machineWith(500.0, 3000.0, 360.0, 1800.0);
    const std::vector<MachineAxes> axes{{0, 0, 0, 0, 0}};
    EXPECT_EQ(blockByBlockTime(axes, std::vector<double>{50.0}, machine).time, 0.0);
}

} // namespace
} // namespace bladeaxis::analysis

// The ball centre between two programmed points as a control without tool-centre-point
// interpolation moves the axes: checked against the arc a turning table sweeps.

#include "core/base/execution.h"
#include "core/base/units.h"
#include "core/kinematics/interpolation_deviation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bladeaxis::kinematics {
namespace {

TEST(InterpolationDeviation, ALinearMoveStaysOnItsChord) {
    const MachineModel machine = defaultBladeMachine();
    const std::vector<MachineAxes> axes{{0, 0, 10, 0, 0}, {5, 3, 12, 0, 0}, {9, -2, 11, 0, 0}};
    EXPECT_NEAR(interpolationDeviation(axes, machine.chain, 4.0).maxMm, 0.0, 1e-12);
}

TEST(InterpolationDeviation, ATableTurnUnderAFixedToolSweepsAnArcAboutTheAxis) {
    // The tool stays put while A turns by dA: the ball centre, at r from the axis, sweeps an arc
    // whose sagitta is r (1 - cos(dA / 2)) at mid-block.
    MachineModel machine = defaultBladeMachine();
    const double radius = 4.0, tipHeight = 16.0, step = units::degToRad(4.0);
    const std::vector<MachineAxes> axes{{0, 0, tipHeight, 0, 0}, {0, 0, tipHeight, step, 0}};
    const InterpolationDeviation deviation = interpolationDeviation(axes, machine.chain, radius, 9);
    const double r = tipHeight + radius;
    EXPECT_NEAR(deviation.maxMm, r * (1.0 - std::cos(step / 2.0)), 1e-9);
    EXPECT_EQ(deviation.block, 1U);
    EXPECT_EQ(deviation.blocks, 1U);
}

TEST(InterpolationDeviation, HalvingTheRotaryStepQuartersTheDeviation) {
    MachineModel machine = defaultBladeMachine();
    const auto deviationFor = [&machine](double stepDeg) {
        const std::vector<MachineAxes> axes{{0, 0, 20, 0, 0},
                                            {0, 0, 20, units::degToRad(stepDeg), 0}};
        return interpolationDeviation(axes, machine.chain, 4.0, 9).maxMm;
    };
    EXPECT_NEAR(deviationFor(2.0) / deviationFor(1.0), 4.0, 0.01);
}

// Long enough for several ranges of threads, with two large turns in different ranges: any
// thread count gives the serial maximum and its block.
TEST(InterpolationDeviation, AnyThreadCountGivesTheSerialMaximumAndItsFirstBlock) {
    const MachineModel machine = defaultBladeMachine();
    std::vector<MachineAxes> axes;
    double a = 0.0;
    for (std::size_t i = 0; i < 100'000; ++i) {
        const bool big = i == 30'000 || i == 80'000; // the same turn twice
        a += units::degToRad(big ? 3.0 : 0.1 + 0.05 * std::sin(0.001 * static_cast<double>(i)));
        axes.push_back({0.01 * static_cast<double>(i % 500), 0, 20, a, 0});
    }
    InterpolationDeviation serial;
    {
        const ThreadCountScope one(1);
        serial = interpolationDeviation(axes, machine.chain, 4.0);
    }
    EXPECT_TRUE(serial.block == 30'000U || serial.block == 80'000U) << serial.block;
    for (unsigned threads : {2U, 3U, 4U}) {
        const ThreadCountScope scope(threads);
        const InterpolationDeviation parallel = interpolationDeviation(axes, machine.chain, 4.0);
        EXPECT_EQ(parallel.maxMm, serial.maxMm) << threads;
        EXPECT_EQ(parallel.block, serial.block) << threads;
        EXPECT_EQ(parallel.blocks, serial.blocks) << threads;
    }
}

TEST(InterpolationDeviation, ACancelledTokenEndsItEarly) {
    const MachineModel machine = defaultBladeMachine();
    std::vector<MachineAxes> axes(200'000, MachineAxes{0, 0, 20, 0, 0});
    axes.back().a = 1.0; // the one turn is in the last block
    CancelToken cancel;
    cancel.requestCancel();
    EXPECT_EQ(interpolationDeviation(axes, machine.chain, 4.0, 3, &cancel).maxMm, 0.0);
    EXPECT_GT(interpolationDeviation(axes, machine.chain, 4.0).maxMm, 0.0);
}

} // namespace
} // namespace bladeaxis::kinematics

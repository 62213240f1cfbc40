// The ball centre between two programmed points as a control without tool-centre-point
// interpolation moves the axes: checked against the arc a turning table sweeps.

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

} // namespace
} // namespace bladeaxis::kinematics

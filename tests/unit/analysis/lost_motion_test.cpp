#include "core/analysis/lost_motion.h"
#include "core/base/units.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::analysis {
namespace {

using kinematics::AxisId;

kinematics::MachineModel machineWithPlay() {
    kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    for (const AxisId axis : kinematics::kAllAxes) {
        machine.limit(axis).backlash = 0.0;
    }
    machine.limit(AxisId::Y).backlash = 0.01;
    machine.limit(AxisId::A).backlash = units::degToRad(0.005);
    return machine;
}

// Y over two revolutions of a helix (four direction changes), A turning with three reversals.
AxisProfile helixProfile(double yNoise) {
    AxisProfile profile;
    auto axes = std::make_shared<std::vector<kinematics::MachineAxes>>();
    for (int i = 0; i <= 400; ++i) {
        const double angle = 4.0 * units::kPi * i / 400.0 + 0.3;
        kinematics::MachineAxes at;
        at.y = 20.0 * std::sin(angle) + (i % 2 == 0 ? yNoise : -yNoise);
        axes->push_back(at);
        profile.sampleRecord.push_back(static_cast<RecordIndex>(i));
    }
    profile.recordAxes = std::move(axes);
    profile.aReversals.count = 3;
    return profile;
}

TEST(LostMotion, EachDirectionChangeOfAnAxisWithPlayTakesUpItsBacklash) {
    const auto losses = lostMotion(helixProfile(0.0), machineWithPlay());
    ASSERT_EQ(losses.size(), 2U) << "only the axes with play";
    EXPECT_EQ(losses[0].axis, AxisId::Y);
    EXPECT_EQ(losses[0].reversals, 4);
    EXPECT_NEAR(losses[0].lostMotion, 0.04, 1e-12);
    EXPECT_EQ(losses[1].axis, AxisId::A);
    EXPECT_EQ(losses[1].reversals, 3);
    EXPECT_NEAR(losses[1].lostMotion, units::degToRad(0.015), 1e-15);
}

TEST(LostMotion, RoundingBelowAMicrometreIsNotADirectionChange) {
    const auto losses = lostMotion(helixProfile(0.4e-6), machineWithPlay());
    ASSERT_FALSE(losses.empty());
    EXPECT_EQ(losses[0].reversals, 4);
}

TEST(LostMotion, AMachineWithoutPlayHasNothingToReport) {
    kinematics::MachineModel machine = machineWithPlay();
    machine.limit(AxisId::Y).backlash = 0.0;
    machine.limit(AxisId::A).backlash = 0.0;
    EXPECT_TRUE(lostMotion(helixProfile(0.0), machine).empty());
}

} // namespace
} // namespace bladeaxis::analysis

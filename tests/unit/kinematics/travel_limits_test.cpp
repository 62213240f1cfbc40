#include "core/kinematics/travel_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bladeaxis::kinematics {
namespace {

MachineModel machineWithTravel() {
    MachineModel machine = defaultBladeMachine();
    machine.limit(AxisId::X) = {.hasTravel = true, .min = -10.0, .max = 10.0};
    machine.limit(AxisId::B) = {.hasTravel = true, .min = -0.5, .max = 0.5};
    machine.limit(AxisId::A).hasTravel = false; // continuous
    return machine;
}

TEST(TravelLimits, AMotionInsideEveryTravelHasNoExcess) {
    const std::vector<MachineAxes> axes{{.x = -10.0, .b = 0.5}, {.x = 10.0, .a = 100.0}};
    EXPECT_FALSE(firstTravelExcess(axes, machineWithTravel()).has_value());
}

TEST(TravelLimits, TheFirstSampleBeyondATravelIsNamedWithItsAxisAndAmount) {
    const std::vector<MachineAxes> axes{{.x = 0.0}, {.x = 10.5}, {.x = 12.0}, {.b = 0.7}};
    const auto excess = firstTravelExcess(axes, machineWithTravel());
    ASSERT_TRUE(excess.has_value());
    EXPECT_EQ(excess->axis, AxisId::X);
    EXPECT_EQ(excess->index, 1U);
    EXPECT_DOUBLE_EQ(excess->amount, 0.5);
    EXPECT_EQ(describe(*excess, machineWithTravel()),
              "X = 10.500 mm, 0.500 mm beyond the travel [-10.000, 10.000] mm");
}

TEST(TravelLimits, RotaryExcessIsDescribedInDegrees) {
    const std::vector<MachineAxes> axes{{.b = -0.6}};
    const auto excess = firstTravelExcess(axes, machineWithTravel());
    ASSERT_TRUE(excess.has_value());
    EXPECT_EQ(excess->axis, AxisId::B);
    EXPECT_NE(describe(*excess, machineWithTravel()).find("B = -34.377 deg"), std::string::npos)
        << describe(*excess, machineWithTravel());
}

TEST(TravelLimits, AContinuousRotaryAxisIsNeverBeyondItsTravel) {
    const std::vector<MachineAxes> axes{{.a = 1e6}, {.a = -1e6}};
    EXPECT_FALSE(firstTravelExcess(axes, machineWithTravel()).has_value());
}

TEST(TravelLimits, ANotANumberAxisValueIsAnExcess) {
    const std::vector<MachineAxes> axes{{.x = std::nan("")}};
    EXPECT_TRUE(firstTravelExcess(axes, machineWithTravel()).has_value());
}

TEST(TravelLimits, TheControlsResolutionIsNotAnExcess) {
    const std::vector<MachineAxes> axes{{.x = 10.0 + 1e-7}};
    EXPECT_FALSE(firstTravelExcess(axes, machineWithTravel()).has_value());
}

// On a table-B machine the engine's y is the program's -X: an excess is told as the program's
// X word with its own value and travel.
TEST(TravelLimits, AnExcessOnATableBMachineIsToldInTheProgramsLetterAndSign) {
    MachineModel machine = defaultBladeMachine();
    machine.layout = Layout::TableBHeadA;
    machine.limit(AxisId::Y) = {.hasTravel = true, .min = -300.0, .max = 100.0}; // X in [-100, 300]
    const std::vector<MachineAxes> axes{{.y = 0.0}, {.y = -301.0}};
    const auto excess = firstTravelExcess(axes, machine);
    ASSERT_TRUE(excess.has_value());
    EXPECT_EQ(describe(*excess, machine),
              "X = 301.000 mm, 1.000 mm beyond the travel [-100.000, 300.000] mm");
}

} // namespace
} // namespace bladeaxis::kinematics

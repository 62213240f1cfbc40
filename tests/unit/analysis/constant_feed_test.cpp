#include "core/analysis/constant_feed.h"
#include "core/base/units.h"
#include "tests/unit/analysis/test_paths.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::analysis {
namespace {

// These paths are analytic: the spline through their points is exact, where the default
// controller filter would round their corners by its 8 ms.
const AxisProfileOptions kExactSpline{.method = DerivativeMethod::Spline};

using kinematics::AxisId;
using Binding = ConstantFeedTime::Binding;

kinematics::MachineModel unlimitedMachine() {
    kinematics::MachineModel machine; // every limit 0 = unlimited
    return machine;
}

// A profile with hand-set path-derivative peaks: |q'| = d1, |q''| = d2, |q'''| = d3 at feed F.
AxisProfile handProfile(double feed, double length) {
    AxisProfile profile;
    profile.feed = feed;
    profile.pathLength = length;
    return profile;
}

void setPathPeaks(AxisProfile& profile, AxisId id, double d1, double d2, double d3) {
    AxisSeries& axis = profile.axes[static_cast<int>(id)];
    const double f = profile.feed;
    axis.peakVelocity = d1 * f;
    axis.peakAcceleration = d2 * f * f;
    axis.peakJerk = d3 * f * f * f;
}

TEST(ConstantFeedTime, ProgrammedFeedBindsWhenEveryAxisIsWithinItsLimits) {
    AxisProfile profile = handProfile(10.0, 300.0);
    setPathPeaks(profile, AxisId::X, 1.0, 0.1, 0.01);
    const ConstantFeedTime t1 =
        constantFeedTime(profile, kinematics::defaultBladeMachine(), /*includeJerk=*/true);
    EXPECT_EQ(t1.binding, Binding::Programmed);
    EXPECT_EQ(t1.achievableFeed, 10.0);
    EXPECT_DOUBLE_EQ(t1.time, 30.0);
    EXPECT_EQ(t1.bindingAxis, AxisId::X); // the axis closest to its limit
}

// Y: |q''| = 0.1 /mm, a = 3000 mm/s^2 -> sqrt(30000) = 173.2 mm/s;
// Z: |q'''| = 0.01 /mm^2, J = 30000 mm/s^3 -> cbrt(3e6) = 144.2 mm/s.
TEST(ConstantFeedTime, ReportsWhichAxisAndWhichLimitBinds) {
    AxisProfile profile = handProfile(400.0, 1000.0);
    setPathPeaks(profile, AxisId::Y, 0.5, 0.1, 0.0);
    setPathPeaks(profile, AxisId::Z, 0.5, 0.0, 0.01);
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();

    const ConstantFeedTime noJerk = constantFeedTime(profile, machine, false);
    EXPECT_EQ(noJerk.binding, Binding::Acceleration);
    EXPECT_EQ(noJerk.bindingAxis, AxisId::Y);
    EXPECT_NEAR(noJerk.achievableFeed, std::sqrt(30000.0), 1e-9);
    EXPECT_NEAR(noJerk.time, 1000.0 / std::sqrt(30000.0), 1e-9);
    EXPECT_EQ(noJerk.feed, 400.0);

    const ConstantFeedTime withJerk = constantFeedTime(profile, machine, true);
    EXPECT_EQ(withJerk.binding, Binding::Jerk);
    EXPECT_EQ(withJerk.bindingAxis, AxisId::Z);
    EXPECT_NEAR(withJerk.achievableFeed, std::cbrt(3e6), 1e-9);

    profile.feed = 1e4; // now X velocity |q'| = 0.5 with 500 mm/s allows 1000 mm/s ...
    setPathPeaks(profile, AxisId::Y, 0.0, 0.0, 0.0);
    setPathPeaks(profile, AxisId::Z, 0.0, 0.0, 0.0);
    setPathPeaks(profile, AxisId::X, 0.5, 0.0, 0.0);
    const ConstantFeedTime velocity = constantFeedTime(profile, machine, true);
    EXPECT_EQ(velocity.binding, Binding::Velocity);
    EXPECT_NEAR(velocity.achievableFeed, 1000.0, 1e-9);
}

TEST(ConstantFeedTime, MissingLimitsAndStillAxesNeverBind) {
    AxisProfile profile = handProfile(50.0, 100.0);
    setPathPeaks(profile, AxisId::A, 3.0, 2.0, 1.0);
    const ConstantFeedTime t1 = constantFeedTime(profile, unlimitedMachine(), true);
    EXPECT_EQ(t1.binding, Binding::Programmed);
    EXPECT_EQ(t1.achievableFeed, 50.0);
    EXPECT_EQ(constantFeedTime(handProfile(0.0, 100.0), unlimitedMachine(), true).time, 0.0);
}

// The known case: tip on a circle of radius r = 10 mm with A = s / r, so |A'| = 0.1 rad/mm.
// The default machine's A limit is 360 deg/s = 2 pi rad/s: F* = 2 pi r = 62.83 mm/s (the linear
// axes allow 173 mm/s by acceleration and 144 mm/s by jerk).
testing::Program circleProgram(double r, double feed) {
    testing::Program program;
    double s = 0.0;
    Vec3 previous = Vec3::Zero();
    for (int i = 0; i < 300; ++i) {
        const double phi = 1.5 * units::kPi * i / 300;
        const Vec3 tip(0.0, r * std::cos(phi), r * std::sin(phi));
        s += i == 0 ? 0.0 : (tip - previous).norm();
        previous = tip;
        program.add(tip, s / r, feed);
    }
    return program;
}

TEST(ConstantFeedTime, CircleWithDefaultMachineIsLimitedByTheAVelocityInRadians) {
    const testing::Program program = circleProgram(10.0, 100.0);
    const Result<AxisProfile> profile =
        analyseAxisMotion(program.axes, program.records, kExactSpline);
    ASSERT_TRUE(profile.has_value());
    const ConstantFeedTime t1 =
        constantFeedTime(*profile, kinematics::defaultBladeMachine(), /*includeJerk=*/true);
    EXPECT_EQ(t1.binding, Binding::Velocity);
    EXPECT_EQ(t1.bindingAxis, AxisId::A);
    EXPECT_NEAR(t1.achievableFeed, 2 * units::kPi * 10.0, 1e-6);
    EXPECT_NEAR(t1.time, profile->pathLength / (20 * units::kPi), 1e-9);
}

// A limit of "360" left in deg/s but read as rad/s changes F* by 180/pi = 57.3: the known case
// above would catch it.
TEST(ConstantFeedTime, DegreeLimitReadAsRadiansWouldChangeTheFeedBy57Times) {
    const testing::Program program = circleProgram(10.0, 1e5);
    const Result<AxisProfile> profile =
        analyseAxisMotion(program.axes, program.records, kExactSpline);
    ASSERT_TRUE(profile.has_value());
    kinematics::MachineModel right = unlimitedMachine();
    right.limit(AxisId::A).velocity = units::degToRad(360.0);
    kinematics::MachineModel wrong = unlimitedMachine();
    wrong.limit(AxisId::A).velocity = 360.0;
    const double good = constantFeedTime(*profile, right, false).achievableFeed;
    const double bad = constantFeedTime(*profile, wrong, false).achievableFeed;
    EXPECT_NEAR(good, 20 * units::kPi, 1e-6);
    EXPECT_NEAR(bad / good, 180.0 / units::kPi, 1e-6);
}

} // namespace
} // namespace bladeaxis::analysis

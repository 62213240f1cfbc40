// The rotary-limit sweep of spec §8.3: faster rotary axes never slow T2 down, and a path that
// does not turn the rotary axes does not care about their limits.

#include "core/analysis/time_optimal_sweep.h"
#include "tests/unit/analysis/test_paths.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::analysis {
namespace {

// X advances 0.1 mm per sample while A turns `aStep` rad per sample, at 2000 mm/min-like feed.
AxisProfile linearPlusRotary(double aStep) {
    testing::Program program;
    for (int i = 0; i < 400; ++i) {
        program.add(Vec3(0.1 * i, 0.0, 0.0), aStep * i, 30.0);
    }
    return *analyseAxisMotion(program.axes, program.records, {});
}

TEST(TimeOptimalSweep, FasterRotaryAxesNeverMakeT2Slower) {
    const auto machine = kinematics::defaultBladeMachine();
    const auto sweep =
        sweepRotaryLimits(linearPlusRotary(0.01), machine, defaultRotarySweepFactors());
    ASSERT_TRUE(sweep.has_value());
    ASSERT_EQ(sweep->size(), defaultRotarySweepFactors().size());
    for (std::size_t k = 1; k < sweep->size(); ++k) {
        ASSERT_TRUE(std::isfinite((*sweep)[k].time));
        EXPECT_LE((*sweep)[k].time, (*sweep)[k - 1].time * (1.0 + 1e-12));
    }
    EXPECT_LT(sweep->back().time, sweep->front().time); // A binds here: the sweep shows it
}

TEST(TimeOptimalSweep, PathWithoutRotaryMotionIgnoresRotaryLimits) {
    const auto machine = kinematics::defaultBladeMachine();
    const auto sweep = sweepRotaryLimits(linearPlusRotary(0.0), machine, {0.5, 2.0});
    ASSERT_TRUE(sweep.has_value());
    EXPECT_DOUBLE_EQ((*sweep)[0].time, (*sweep)[1].time);
}

TEST(TimeOptimalSweep, NonPositiveFactorIsAnError) {
    const auto machine = kinematics::defaultBladeMachine();
    EXPECT_FALSE(sweepRotaryLimits(linearPlusRotary(0.01), machine, {1.0, 0.0}).has_value());
    EXPECT_FALSE(sweepRotaryLimits(linearPlusRotary(0.01), machine, {NAN}).has_value());
}

} // namespace
} // namespace bladeaxis::analysis

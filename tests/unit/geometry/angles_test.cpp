#include "core/base/units.h"
#include "core/geometry/angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace bladeaxis::geometry {
namespace {

using units::kPi;
using units::kTwoPi;

TEST(WrapAngle, MapsIntoHalfOpenRangeAndKeepsTheAngle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> any(-1000.0, 1000.0);
    std::vector<double> angles{0.0, kPi, -kPi, 3 * kPi, -3 * kPi, kTwoPi, -kTwoPi, 1e-300, 1e6};
    for (int i = 0; i < 1000; ++i) {
        angles.push_back(any(rng));
    }
    for (double angle : angles) {
        const double wrapped = wrapAngle(angle);
        EXPECT_GT(wrapped, -kPi) << angle;
        EXPECT_LE(wrapped, kPi) << angle;
        const double turns = (angle - wrapped) / kTwoPi;
        EXPECT_NEAR(turns, std::round(turns), 1e-9) << angle;
    }
}

TEST(WrapAngle, SendsBothEndsOfTheCircleToPlusPi) {
    EXPECT_EQ(wrapAngle(kPi), kPi);
    EXPECT_EQ(wrapAngle(-kPi), kPi);
    EXPECT_NEAR(wrapAngle(-3 * kPi), kPi, 1e-12);
    EXPECT_EQ(wrapAngle(0.5), 0.5);
    EXPECT_EQ(wrapAngle(-0.5), -0.5);
}

TEST(UnwrapNear, ReturnsTheEquivalentAngleWithinHalfATurnOfTheReference) {
    EXPECT_NEAR(unwrapNear(0.1, 10 * kTwoPi), 10 * kTwoPi + 0.1, 1e-12);
    EXPECT_NEAR(unwrapNear(-0.1, -kPi + 0.05), -0.1, 1e-12);
    const double result = unwrapNear(-3.0, 3.0); // shortest way is +2pi - 6 = 0.283 forward
    EXPECT_NEAR(result, kTwoPi - 3.0, 1e-12);
    EXPECT_LE(result - 3.0, kPi);
    EXPECT_GT(result - 3.0, -kPi);
}

TEST(Unwrap, OfWrappedSequenceReproducesEverySequenceWithStepsBelowPi) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> step(-0.99 * kPi, 0.99 * kPi);
    std::uniform_real_distribution<double> start(-kPi + 1e-9, kPi);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<double> original{start(rng)};
        for (int i = 0; i < 500; ++i) {
            original.push_back(original.back() + step(rng));
        }
        std::vector<double> wrapped;
        for (double a : original) {
            wrapped.push_back(wrapAngle(a));
        }
        const std::vector<double> restored = unwrap(wrapped);
        ASSERT_EQ(restored.size(), original.size());
        for (std::size_t i = 0; i < original.size(); ++i) {
            ASSERT_NEAR(restored[i], original[i], 1e-9) << "trial " << trial << " index " << i;
        }
    }
}

TEST(Unwrap, TakesTheShortWayAcrossTheSeam) {
    const std::vector<double> modulo{units::degToRad(350.0), units::degToRad(10.0),
                                     units::degToRad(340.0)};
    const std::vector<double> result = unwrap(modulo);
    EXPECT_NEAR(units::radToDeg(result[1]), 370.0, 1e-9);
    EXPECT_NEAR(units::radToDeg(result[2]), 340.0, 1e-9);
}

TEST(Unwrap, HandlesEmptyAndSingleInputs) {
    EXPECT_TRUE(unwrap({}).empty());
    const std::vector<double> one{5.0};
    EXPECT_EQ(unwrap(one), one);
}

} // namespace
} // namespace bladeaxis::geometry

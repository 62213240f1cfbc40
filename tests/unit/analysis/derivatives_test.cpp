#include "core/analysis/derivatives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace bladeaxis::analysis {
namespace {

std::vector<double> randomGrid(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> gap(0.01, 3.0);
    std::vector<double> s{0.0};
    for (int i = 1; i < count; ++i) {
        s.push_back(s.back() + gap(rng));
    }
    return s;
}

TEST(FiniteDifferences, AreExactForQuadraticsOnRandomNonUniformGrids) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> coefficient(-3.0, 3.0);
    const double feed = 7.0;
    for (int count : {3, 4, 9, 200}) {
        for (int trial = 0; trial < 10; ++trial) {
            const double b = coefficient(rng);
            const double c = coefficient(rng);
            const std::vector<double> s = randomGrid(rng, count);
            std::vector<double> q;
            for (double x : s) {
                q.push_back(1.0 + b * x + c * x * x);
            }
            const Result<AxisSeries> series =
                differentiateAxis(s, q, feed, DerivativeMethod::FiniteDifference);
            ASSERT_TRUE(series.has_value()) << series.error().toString();
            const double scale = 1.0 + s.back() * s.back(); // rounding grows with |q|
            for (std::size_t i = 0; i < s.size(); ++i) {
                EXPECT_NEAR(series->velocity[i], (b + 2 * c * s[i]) * feed, 1e-9 * scale) << i;
                EXPECT_NEAR(series->acceleration[i], 2 * c * feed * feed, 1e-8 * scale) << i;
                EXPECT_NEAR(series->jerk[i], 0.0, 1e-6 * scale) << i;
            }
        }
    }
}

TEST(FiniteDifferences, TwoSamplesGiveTheChordSlope) {
    const std::vector<double> s{0.0, 2.0};
    const Result<AxisSeries> series =
        differentiateAxis(s, {1.0, 5.0}, 3.0, DerivativeMethod::FiniteDifference);
    ASSERT_TRUE(series.has_value());
    EXPECT_DOUBLE_EQ(series->velocity[0], 6.0);
    EXPECT_DOUBLE_EQ(series->velocity[1], 6.0);
    EXPECT_EQ(series->peakAcceleration, 0.0);
}

TEST(SplineDerivatives, AreExactForCubicsAndScaleWithPowersOfTheFeed) {
    std::mt19937 rng(23);
    const std::vector<double> s = randomGrid(rng, 40);
    std::vector<double> q;
    for (double x : s) {
        q.push_back(0.5 - x + 0.25 * x * x + 0.01 * x * x * x);
    }
    const double feed = 2.0;
    const Result<AxisSeries> series = differentiateAxis(s, q, feed, DerivativeMethod::Spline);
    ASSERT_TRUE(series.has_value());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double x = s[i];
        EXPECT_NEAR(series->velocity[i], (-1 + 0.5 * x + 0.03 * x * x) * feed, 1e-7) << i;
        EXPECT_NEAR(series->acceleration[i], (0.5 + 0.06 * x) * feed * feed, 1e-7) << i;
        EXPECT_NEAR(series->jerk[i], 0.06 * feed * feed * feed, 1e-7) << i;
    }
    EXPECT_NEAR(series->peakJerk, 0.06 * 8.0, 1e-7);
}

// q = s - s^3/3 has q' = 1 - s^2: 0 at the knots -1 and 1 but 1 at s = 0, inside the first
// interval. The peak must come from the interior points s = -1 + 2k/5: max |q'| = 1 - 0.04.
TEST(SplineDerivatives, PeakVelocityIncludesFourInteriorPointsPerInterval) {
    const std::vector<double> s{-1.0, 1.0, 1.2, 1.3};
    std::vector<double> q;
    for (double x : s) {
        q.push_back(x - x * x * x / 3.0);
    }
    const Result<AxisSeries> series = differentiateAxis(s, q, 10.0, DerivativeMethod::Spline);
    ASSERT_TRUE(series.has_value());
    EXPECT_NEAR(series->peakVelocity, 0.96 * 10.0, 1e-9);
    EXPECT_NEAR(std::abs(series->velocity.back()), 0.69 * 10.0, 1e-9);
}

TEST(DifferentiateAxis, RejectsBadSamplesInsteadOfReturningGarbage) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> s{0.0, 1.0, 2.0};
    for (DerivativeMethod method : {DerivativeMethod::Spline, DerivativeMethod::FiniteDifference}) {
        EXPECT_FALSE(differentiateAxis(s, {0.0, nan, 1.0}, 1.0, method).has_value());
        EXPECT_FALSE(
            differentiateAxis(std::vector<double>{0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}, 1.0, method)
                .has_value());
        EXPECT_FALSE(differentiateAxis(s, {0.0, 1.0}, 1.0, method).has_value());
        EXPECT_FALSE(differentiateAxis(s, {0.0, 1.0, 2.0}, 0.0, method).has_value());
        EXPECT_FALSE(differentiateAxis(s, {0.0, 1.0, 2.0}, nan, method).has_value());
        const Result<AxisSeries> one =
            differentiateAxis(std::vector<double>{0.0}, {4.0}, 1.0, method);
        ASSERT_TRUE(one.has_value());
        EXPECT_EQ(one->velocity, std::vector<double>{0.0});
        EXPECT_TRUE(differentiateAxis({}, {}, 1.0, method).has_value());
    }
}

TEST(AbsPercentile, InterpolatesBetweenOrderStatisticsOfMagnitudes) {
    std::vector<double> values;
    for (int i = 1; i <= 1001; ++i) {
        values.push_back(i % 2 == 0 ? -i : i);
    }
    EXPECT_NEAR(absPercentile(values, 0.999), 1000.0, 1e-9); // rank 0.999 * 1000 = 999
    EXPECT_DOUBLE_EQ(absPercentile(values, 0.5), 501.0);
    EXPECT_DOUBLE_EQ(absPercentile(std::vector<double>{-1.0, 3.0}, 0.25), 1.5);
    EXPECT_DOUBLE_EQ(absPercentile(std::vector<double>{-1.0, 3.0}, 1.0), 3.0);
    EXPECT_EQ(absPercentile({}, 0.999), 0.0);
}

TEST(AbsPercentile, RanksNanAboveEveryNumber) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> values{nan, 1.0, -2.0, nan, 3.0};
    EXPECT_DOUBLE_EQ(absPercentile(values, 0.5), 3.0);
}

} // namespace
} // namespace bladeaxis::analysis

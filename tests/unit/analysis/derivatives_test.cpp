#include "core/analysis/derivatives.h"
#include "core/base/execution.h"
#include "core/geometry/cubic_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <string>
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
            }
            EXPECT_NEAR(series->peakJerk, 0.0, 1e-6 * scale);
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
        EXPECT_TRUE(one->still()); // one sample: at rest
        EXPECT_EQ(one->velocities(1), std::vector<double>{0.0});
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

// Random axes over one random grid: a wavy one, a noisy one, one with a jump and a still one.
std::vector<std::vector<double>> randomAxes(std::mt19937& rng, const std::vector<double>& s) {
    std::uniform_real_distribution<double> noise(-1.0, 1.0);
    std::vector<std::vector<double>> axes(4);
    for (std::size_t i = 0; i < s.size(); ++i) {
        axes[0].push_back(std::sin(0.7 * s[i]));
        axes[1].push_back(noise(rng));
        axes[2].push_back(i < s.size() / 2 ? 0.0 : 3.0);
        axes[3].push_back(2.5);
    }
    return axes;
}

// Every other sample a knot, plus the last.
std::vector<std::size_t> everyOtherSample(std::size_t n) {
    std::vector<std::size_t> knots;
    for (std::size_t i = 0; i + 1 < n; i += 2) {
        knots.push_back(i);
    }
    knots.push_back(n - 1);
    return knots;
}

void expectSameSeries(const AxisSeries& a, const AxisSeries& b) {
    EXPECT_EQ(a.minPosition, b.minPosition);
    EXPECT_EQ(a.maxPosition, b.maxPosition);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.acceleration, b.acceleration);
    EXPECT_EQ(a.peakVelocity, b.peakVelocity);
    EXPECT_EQ(a.peakAcceleration, b.peakAcceleration);
    EXPECT_EQ(a.peakJerk, b.peakJerk);
    EXPECT_EQ(a.p999Velocity, b.p999Velocity);
    EXPECT_EQ(a.p999Acceleration, b.p999Acceleration);
}

TEST(DifferentiateAxes, GiveEachAxisExactlyWhatDifferentiateAxisGives) {
    std::mt19937 rng(29);
    for (int count : {2, 3, 4, 7, 300}) {
        const std::vector<double> s = randomGrid(rng, count);
        const std::vector<std::vector<double>> axes = randomAxes(rng, s);
        const std::vector<std::size_t> knots = everyOtherSample(s.size());
        for (DerivativeMethod method :
             {DerivativeMethod::Spline, DerivativeMethod::RawSpline,
              DerivativeMethod::FiniteDifference, DerivativeMethod::Filtered}) {
            const std::vector<Result<AxisSeries>> together =
                differentiateAxes(s, axes, 3.0, method, 0.008, knots);
            ASSERT_EQ(together.size(), axes.size());
            for (std::size_t k = 0; k < axes.size(); ++k) {
                const Result<AxisSeries> alone =
                    differentiateAxis(s, axes[k], 3.0, method, 0.008, knots);
                ASSERT_TRUE(alone.has_value() && together[k].has_value()) << count << " " << k;
                expectSameSeries(*together[k], *alone);
            }
        }
    }
}

// Positions handed out one axis at a time, into the scratch the differentiation lends, give what
// the same positions held all at once give; each axis is asked for exactly once. The spline
// methods write the velocities over the scratch: with every sample a knot (no knot list, or
// the raw spline) the positions they read are the ones being replaced.
TEST(DifferentiateAxes, PositionsHandedOutPerAxisGiveWhatHeldPositionsGive) {
    std::mt19937 rng(31);
    const std::vector<double> s = randomGrid(rng, 500);
    std::vector<std::vector<double>> axes = randomAxes(rng, s);
    axes.push_back(std::vector<double>(s.size(), 0.25)); // a still axis
    for (const std::vector<std::size_t>& knots :
         {everyOtherSample(s.size()), std::vector<std::size_t>{}}) {
        for (DerivativeMethod method : {DerivativeMethod::Spline, DerivativeMethod::RawSpline,
                                        DerivativeMethod::FiniteDifference}) {
            for (unsigned threads : {1u, 2u}) {
                const ThreadCountScope scope(threads);
                std::vector<int> asked(axes.size(), 0);
                std::mutex askedMutex;
                const PositionsOf copied = [&](std::size_t k, std::vector<double>& scratch) {
                    const std::lock_guard lock(askedMutex);
                    ++asked[k];
                    scratch = axes[k];
                    return std::span<const double>(scratch);
                };
                const auto handedOut =
                    differentiateAxes(s, axes.size(), copied, 2.0, method, 0.008, knots);
                const auto held = differentiateAxes(s, axes, 2.0, method, 0.008, knots);
                ASSERT_EQ(handedOut.size(), held.size());
                for (std::size_t k = 0; k < axes.size(); ++k) {
                    EXPECT_EQ(asked[k], 1) << k;
                    ASSERT_TRUE(handedOut[k].has_value() && held[k].has_value()) << k;
                    expectSameSeries(*handedOut[k], *held[k]);
                }
                EXPECT_TRUE(handedOut.back()->still());
            }
        }
    }
}

// On one thread the axes go in order: the token set while the first axis's positions are
// handed out stops that axis before its fit (its positions may have taken long to compute) and
// every later one before it starts.
TEST(DifferentiateAxes, AnAxisCancelledWhileItsPositionsAreHandedOutIsNotDifferentiated) {
    std::mt19937 rng(37);
    const std::vector<double> s = randomGrid(rng, 200);
    const std::vector<std::vector<double>> axes = randomAxes(rng, s);
    ASSERT_GE(axes.size(), 2u);
    for (DerivativeMethod method : {DerivativeMethod::Spline, DerivativeMethod::FiniteDifference,
                                    DerivativeMethod::Filtered}) {
        CancelToken cancel;
        std::vector<int> asked(axes.size(), 0);
        const PositionsOf cancelling = [&](std::size_t k, std::vector<double>&) {
            ++asked[k];
            cancel.requestCancel();
            return std::span<const double>(axes[k]);
        };
        const auto results =
            differentiateAxes(s, axes.size(), cancelling, 2.0, method, 0.008, {}, &cancel);
        ASSERT_EQ(results.size(), axes.size());
        EXPECT_EQ(asked[0], 1);
        for (std::size_t k = 0; k < axes.size(); ++k) {
            ASSERT_FALSE(results[k].has_value()) << k;
            EXPECT_EQ(results[k].error().code, ErrorCode::Cancelled) << k;
            EXPECT_EQ(asked[k], k == 0 ? 1 : 0) << k;
        }
    }
}

TEST(DifferentiateAxes, ReportErrorsPerAxis) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> s{0.0, 1.0, 2.0, 3.0};
    const std::vector<std::vector<double>> axes{
        {0.0, 1.0, 4.0, 9.0}, {0.0, nan, 1.0, 2.0}, {1.0, 1.0, 1.0, 1.0}, {0.0, 1.0}};
    const std::vector<Result<AxisSeries>> results =
        differentiateAxes(s, axes, 1.0, DerivativeMethod::Spline);
    ASSERT_EQ(results.size(), 4u);
    EXPECT_TRUE(results[0].has_value());
    ASSERT_FALSE(results[1].has_value());
    EXPECT_NE(results[1].error().message.find("sample 1"), std::string::npos);
    EXPECT_TRUE(results[2].has_value());
    EXPECT_FALSE(results[3].has_value());
    // Knots that miss the last sample fail every moving axis; a still axis needs no knots.
    const std::vector<std::size_t> badKnots{0, 2};
    const std::vector<Result<AxisSeries>> knotted = differentiateAxes(
        s, std::vector{axes[0], axes[2]}, 1.0, DerivativeMethod::Spline, 0.008, badKnots);
    EXPECT_FALSE(knotted[0].has_value());
    EXPECT_TRUE(knotted[1].has_value());
}

// The peak velocity is the largest |q'| at the samples and at 4 interior points per interval,
// whatever intervals the evaluation skips as unable to raise it.
TEST(SplineDerivatives, PeakVelocityIsTheLargestAtSamplesAndInteriorPoints) {
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> noise(-1.0, 1.0);
    const double feed = 4.0;
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<double> s = randomGrid(rng, 5 + trial % 20);
        std::vector<double> q;
        for (double x : s) {
            q.push_back(trial % 2 == 0 ? noise(rng) : std::sin(x) + 1e-3 * noise(rng));
        }
        const Result<AxisSeries> series = differentiateAxis(s, q, feed, DerivativeMethod::Spline);
        ASSERT_TRUE(series.has_value());
        const geometry::CubicSpline spline(s, q);
        double expected = 0.0;
        for (double v : series->velocity) {
            expected = std::max(expected, std::abs(v));
        }
        double interior = 0.0;
        for (std::size_t i = 0; i + 1 < s.size(); ++i) {
            for (int k = 1; k <= 4; ++k) {
                const double x = s[i] + 0.2 * k * (s[i + 1] - s[i]);
                interior = std::max(interior, std::abs(spline.firstDerivative(i, x)));
            }
        }
        EXPECT_EQ(series->peakVelocity, std::max(expected, interior * feed)) << trial;
    }
}

// The sorted-copy definition of absPercentile, to check the heap that keeps the largest ones.
double sortedAbsPercentile(std::vector<double> values, double p) {
    for (double& v : values) {
        v = std::isnan(v) ? HUGE_VAL : std::abs(v);
    }
    std::ranges::sort(values);
    const double position = std::min(p, 1.0) * static_cast<double>(values.size() - 1);
    const auto k = static_cast<std::size_t>(position);
    const double fraction = position - static_cast<double>(k);
    if (fraction == 0.0 || k + 1 >= values.size()) {
        return values[k];
    }
    return values[k] + fraction * (values[k + 1] - values[k]);
}

TEST(AbsPercentile, MatchesTheSortedCopyExactly) {
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> value(-10.0, 10.0);
    std::uniform_int_distribution<int> small(-2, 2);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int count : {1, 2, 3, 10, 1001, 5000}) {
        std::vector<double> values;
        for (int i = 0; i < count; ++i) {
            const int kind = i % 7;
            values.push_back(kind == 0 ? small(rng) : kind == 1 && i % 3 == 0 ? nan : value(rng));
        }
        for (double p : {0.0, 0.1, 0.5, 0.9, 0.999, 1.0}) {
            const double expected = sortedAbsPercentile(values, p);
            const double actual = absPercentile(values, p);
            if (std::isnan(expected)) {
                EXPECT_TRUE(std::isnan(actual)) << count << " " << p;
            } else {
                EXPECT_EQ(actual, expected) << count << " " << p;
            }
        }
    }
}

} // namespace
} // namespace bladeaxis::analysis

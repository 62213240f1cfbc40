#include "core/analysis/controller_filter.h"
#include "core/analysis/derivatives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace bladeaxis::analysis {
namespace {

TEST(MovingAverage, KeepsConstantsAndLinesAwayFromTheEnds) {
    std::vector<double> line;
    for (int k = 0; k < 50; ++k) {
        line.push_back(3.0 * k - 2.0);
    }
    const auto smoothed = movingAverage(line, 9);
    for (std::size_t k = 4; k + 4 < line.size(); ++k) {
        EXPECT_NEAR(smoothed[k], line[k], 1e-12) << k;
    }
    EXPECT_EQ(movingAverage(std::vector<double>(7, 2.5), 5), std::vector<double>(7, 2.5));
}

// In place, over series shorter than a window, around the fresh sums (every 256 outputs) and
// at both reflected ends, the average is the one into a second series, bit for bit.
TEST(MovingAverage, InPlaceGivesTheBitsOfASecondSeries) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-1000.0, 1000.0);
    for (std::size_t n : {0u, 1u, 2u, 5u, 9u, 17u, 255u, 256u, 257u, 600u}) {
        std::vector<double> series(n);
        for (double& x : series) {
            x = value(random);
        }
        for (std::size_t width : {1u, 2u, 3u, 8u, 9u, 17u, 40u}) {
            std::vector<double> expected;
            movingAverageInto(series, width, expected);
            std::vector<double> inPlace = series;
            movingAverageInPlace(inPlace, width);
            EXPECT_EQ(inPlace, expected) << n << " values, width " << width;
        }
    }
}

TEST(ControllerFilter, ConstantRateAxisKeepsItsVelocity) {
    // s from 0 to 100 mm at 10 mm/s: 10 s; the axis moves 2 units per mm -> 20 units/s.
    std::vector<double> s, q;
    for (int i = 0; i <= 200; ++i) {
        s.push_back(0.5 * i);
        q.push_back(1.0 * i);
    }
    const FilteredAxis axis = filterAxis(s, q, 10.0, 0.008);
    ASSERT_GT(axis.velocity.size(), 9000u);
    const std::size_t middle = axis.velocity.size() / 2;
    EXPECT_NEAR(axis.velocity[middle], 20.0, 1e-9);
    EXPECT_NEAR(axis.acceleration[middle], 0.0, 1e-6);
}

TEST(ControllerFilter, TurnsAVelocityStepIntoABoundedAcceleration) {
    // A corner: the axis stands still, then moves at 1 unit/mm. Raw second differences are an
    // impulse that grows without bound as the samples get denser; the filter's is bounded by
    // the jump divided by the window.
    std::vector<double> s, q;
    for (int i = 0; i <= 2000; ++i) {
        s.push_back(0.01 * i);
        q.push_back(i < 1000 ? 0.0 : 0.01 * (i - 1000));
    }
    const double feed = 10.0, window = 0.008;
    auto filtered = differentiateAxis(s, q, feed, DerivativeMethod::Filtered, window);
    auto raw = differentiateAxis(s, q, feed, DerivativeMethod::FiniteDifference);
    ASSERT_TRUE(filtered && raw);
    const double jump = 1.0 * feed; // units/s
    EXPECT_NEAR(filtered->peakVelocity, jump, 1e-6);
    EXPECT_LE(filtered->peakAcceleration, 1.05 * jump / window);
    EXPECT_GT(filtered->peakAcceleration, 0.5 * jump / window);
    EXPECT_GT(raw->peakAcceleration, 5.0 * filtered->peakAcceleration);
}

TEST(ControllerFilter, AnAxisMovingFromTheFirstSampleShowsNoStartUpOrEndPeak) {
    // The pass starts and ends with the axis turning at 20 units/s: the program commands no
    // acceleration anywhere, so none may appear at the ends of the window.
    std::vector<double> s, q;
    for (int i = 0; i <= 137; ++i) {
        s.push_back(0.37 * i);
        q.push_back(0.74 * i + 5.0);
    }
    const auto filtered = differentiateAxis(s, q, 10.0, DerivativeMethod::Filtered, 0.008);
    ASSERT_TRUE(filtered.has_value());
    EXPECT_NEAR(filtered->peakVelocity, 20.0, 1e-6);
    EXPECT_LT(filtered->peakAcceleration, 1e-4); // round-off; holding the ends gave 20 / 0.008
}

TEST(ControllerFilter, WiderWindowLowersThePeakAcceleration) {
    std::vector<double> s, q;
    for (int i = 0; i <= 400; ++i) {
        s.push_back(0.25 * i);
        q.push_back(std::sin(0.05 * i) + (i > 200 ? 0.02 * (i - 200) : 0.0));
    }
    auto narrow = differentiateAxis(s, q, 20.0, DerivativeMethod::Filtered, 0.004);
    auto wide = differentiateAxis(s, q, 20.0, DerivativeMethod::Filtered, 0.032);
    ASSERT_TRUE(narrow && wide);
    EXPECT_LT(wide->peakAcceleration, narrow->peakAcceleration);
}

// A 10-block program with one Z3000000. took 4.7 GB (Z3.6e8 or a feed of 0.1 mm/min: bad_alloc,
// exit 1): the filter resamples the pass every millisecond, so its memory follows the cycle time.
TEST(ControllerFilter, APassLongerThanItsSampleLimitIsRefusedNamingTheLimitAndTheSplineMethod) {
    const std::vector<double> s{0.0, 10.0, 3.6e8 + 10.0};
    const std::vector<double> q{0.0, 1.0, 3.6e8};
    const double feed = 0.1 / 60.0; // mm/s: 2e14 ms of motion, beyond any memory
    const auto filtered = differentiateAxis(s, q, feed, DerivativeMethod::Filtered, 0.008);
    ASSERT_FALSE(filtered.has_value());
    EXPECT_EQ(filtered.error().code, ErrorCode::Geometry);
    EXPECT_NE(filtered.error().message.find("limit of 50 million"), std::string::npos)
        << filtered.error().message;
    EXPECT_NE(filtered.error().message.find("--derivatives spline"), std::string::npos);
    const auto spline = differentiateAxis(s, q, feed, DerivativeMethod::Spline);
    EXPECT_TRUE(spline.has_value()) << "the way out the message names works";
}

TEST(ControllerFilter, APassWithinItsSampleLimitIsStillFiltered) {
    const double seconds = static_cast<double>(kMaxFilterSamples) * 1e-3 / 1000.0; // a 1000th
    const std::vector<double> s{0.0, seconds * 10.0};
    const std::vector<double> q{0.0, 1.0};
    EXPECT_TRUE(differentiateAxis(s, q, 10.0, DerivativeMethod::Filtered, 0.008).has_value());
}

} // namespace
} // namespace bladeaxis::analysis

// Spec §10.1 rows "channel" and "monotone hull".
#include "core/scheduling/channel.h"
#include "core/scheduling/tangents.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RawChannel, ConvexPolygonWidthIsPiPlusTurningMinusTwiceTheTaper) {
    std::vector<Vec2> points;
    for (int turn = 0; turn < 2; ++turn) {
        for (const Vec2& p : testing::regularPolygon(7, 30.0, 0.3)) {
            points.push_back(p);
        }
    }
    auto field = computeTangents(points, 1.0, 0.0);
    ASSERT_TRUE(field.has_value());
    for (double taper : {0.0, 0.1}) {
        const RawChannel channel = buildRawChannel(*field, {}, taper);
        for (std::size_t i = 1; i + 1 < points.size(); ++i) {
            EXPECT_NEAR(field->turning[i], 2.0 * kPi / 7.0, 1e-12);
            EXPECT_NEAR(channel.thetaMax[i] - channel.thetaMin[i],
                        kPi + field->turning[i] - 2.0 * taper, 1e-12);
            // The forward limit is the outgoing edge direction, rotated inward by the taper.
            const Vec2 edge = points[i + 1] - points[i];
            EXPECT_NEAR(std::remainder(channel.thetaMax[i] + taper - std::atan2(edge.y(), edge.x()),
                                       2.0 * kPi),
                        0.0, 1e-12);
        }
    }
}

TEST(RawChannel, CircleWidthIsPiPlusChordOverRadius) {
    const double r = 40.0;
    const std::vector<Vec2> points = testing::regularPolygon(2000, r);
    auto field = computeTangents(points, 0.5, 3.0);
    ASSERT_TRUE(field.has_value());
    const RawChannel channel = buildRawChannel(*field, {}, 0.0);
    std::size_t steps = 1; // the first chord reaching l_t = 0.5 mm
    while ((points[steps] - points[0]).norm() < 0.5) {
        ++steps;
    }
    const double chord = (points[steps] - points[0]).norm();
    for (std::size_t i = 10; i < 1990; i += 101) {
        const double width = channel.thetaMax[i] - channel.thetaMin[i];
        EXPECT_NEAR(width, kPi + 2.0 * std::asin(chord / (2.0 * r)), 1e-12);
        EXPECT_NEAR(width, kPi + chord / r, 1e-6);
    }
}

TEST(RawChannel, ConcaveRunTakesTheExitForwardAndTheEntryBackwardLimits) {
    std::vector<Vec2> points;
    for (int k = -60; k <= 60; ++k) { // S-shaped: y = -x^3 / 400 ... any shape will do
        const double x = 0.5 * k;
        points.emplace_back(x, 0.002 * x * x * (k < 0 ? -1.0 : 1.0));
    }
    auto field = computeTangents(points, 0.5, 3.0);
    ASSERT_TRUE(field.has_value());
    const RawChannel local = buildRawChannel(*field, {}, 0.0);
    const ConcaveRun run{20, 50, 15.0, 0.0};
    const RawChannel channel = buildRawChannel(*field, std::vector<ConcaveRun>{run}, 0.0);
    for (std::size_t j = 20; j < 50; ++j) {
        EXPECT_EQ(channel.thetaMax[j], local.thetaMax[50]);
        EXPECT_EQ(channel.thetaMin[j], local.thetaMin[20]);
    }
    EXPECT_EQ(channel.thetaMax[50], local.thetaMax[50]);
    EXPECT_EQ(channel.thetaMin[19], local.thetaMin[19]);
}

std::vector<double> randomWalk(std::mt19937& random, std::size_t n, double offset) {
    std::uniform_real_distribution<double> step(-0.3, 0.5);
    std::vector<double> values{offset};
    for (std::size_t i = 1; i < n; ++i) {
        values.push_back(values.back() + step(random));
    }
    return values;
}

TEST(MonotoneHull, IsNonDecreasingInsideTheShrunkChannelAndIdempotent) {
    std::mt19937 random(11);
    for (int trial = 0; trial < 50; ++trial) {
        const std::vector<double> low = randomWalk(random, 200, 0.0);
        std::vector<double> high = low;
        for (double& h : high) {
            h += 4.0;
        }
        const double m = 0.05;
        const MonotoneHull hull = monotoneHull(low, high, m);
        for (std::size_t i = 0; i < low.size(); ++i) {
            EXPECT_LE(hull.hi[i], high[i] - hull.marginHi[i] + 1e-15);
            EXPECT_GE(hull.lo[i], low[i] + hull.marginLo[i] - 1e-15);
            if (i > 0) {
                EXPECT_GE(hull.hi[i], hull.hi[i - 1]);
                EXPECT_GE(hull.lo[i], hull.lo[i - 1]);
            }
        }
        if (!hull.pinched) {
            EXPECT_EQ(*std::min_element(hull.marginHi.begin(), hull.marginHi.end()), m);
        }
        const MonotoneHull again = monotoneHull(hull.lo0, hull.hi0, 0.0);
        EXPECT_EQ(again.lo, hull.lo0);
        EXPECT_EQ(again.hi, hull.hi0);
    }
}

// The lossless lemma of §2.5: a non-decreasing sequence lies inside the raw shrunk channel iff
// it lies inside the hull.
TEST(MonotoneHull, LosslessForMonotoneSequences) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> step(0.0, 0.3);
    std::size_t insideCount = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const std::vector<double> low = randomWalk(random, 30, -1.0);
        std::vector<double> high = randomWalk(random, 30, 1.0);
        const MonotoneHull hull = monotoneHull(low, high, 0.0);
        std::vector<double> theta{step(random) - 0.5};
        for (int i = 1; i < 30; ++i) {
            theta.push_back(theta.back() + step(random));
        }
        bool inRaw = true;
        bool inHull = true;
        for (std::size_t i = 0; i < theta.size(); ++i) {
            inRaw = inRaw && theta[i] >= low[i] && theta[i] <= high[i];
            inHull = inHull && theta[i] >= hull.lo[i] && theta[i] <= hull.hi[i];
        }
        EXPECT_EQ(inRaw, inHull) << trial;
        insideCount += inRaw ? 1 : 0;
    }
    EXPECT_GT(insideCount, 0u); // the property was exercised on both sides
    EXPECT_LT(insideCount, 2000u);
}

TEST(MonotoneHull, PinchIsRelievedLocallyAndEmptyHullIsInfeasible) {
    // A drop of thetaMax to 0.08 after thetaMin reached 0: width 0.08 < 2 m = 0.1.
    const std::vector<double> low{-1.0, -1.0, 0.0, 0.0, 0.0, 0.0, -1.0, 5.0};
    const std::vector<double> high{2.0, 2.0, 2.0, 0.08, 2.0, 3.0, 6.0, 10.0};
    const MonotoneHull hull = monotoneHull(low, high, 0.05);
    EXPECT_TRUE(hull.pinched);
    EXPECT_FALSE(hull.infeasible);
    EXPECT_NEAR(hull.marginHi[3], 0.04, 1e-15);
    EXPECT_EQ(hull.marginHi[7], 0.05); // far from the pinch: full margin
    for (std::size_t i = 0; i < low.size(); ++i) {
        EXPECT_LE(hull.lo[i], hull.hi[i] + 1e-15);
    }
    const std::vector<double> crossing{2.0, 2.0, 2.0, -0.5, 2.0, 3.0, 6.0, 10.0};
    EXPECT_TRUE(monotoneHull(low, crossing, 0.05).infeasible);
}

} // namespace
} // namespace bladeaxis::scheduling

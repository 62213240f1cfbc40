// Spec §10.1 rows "angles and unwrap", "tangents and turning", "curvature sign".
#include "core/geometry/angles.h"
#include "core/scheduling/curvature_states.h"
#include "core/scheduling/detail/fast_angles.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/tangents.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PlaneAngle, AxisFromAngleRoundTripsAndKeepsTheTilt) {
    for (int sign : {1, -1}) {
        for (double angle = -3.0; angle <= 3.0; angle += 0.37) {
            const Vec3 v = axisFromPlaneAngle(angle, 0.0873, sign);
            EXPECT_NEAR(v.norm(), 1.0, 1e-15);
            EXPECT_NEAR(v.x(), std::sin(0.0873), 1e-15);
            EXPECT_NEAR(planeAngle(v, sign), angle, 1e-12);
        }
    }
}

TEST(PlaneAngle, RotationAboutTheAxisShiftsTheAngleInTheFeedSense) {
    const Vec3 v = Vec3(0.1, 0.3, 0.9).normalized();
    const double phi = 0.7;
    const Vec3 rotated = rotationX(phi) * v;
    EXPECT_NEAR(geometry::wrapAngle(planeAngle(rotated, +1) - planeAngle(v, +1)), phi, 1e-12);
    EXPECT_NEAR(geometry::wrapAngle(planeAngle(rotated, -1) - planeAngle(v, -1)), -phi, 1e-12);
}

// The chord and axis angles use detail::atan2: it must agree with the library to a few ulp in
// every quadrant, for tiny and huge ratios, and keep the signed-zero and degenerate cases.
TEST(FastAtan2, AgreesWithTheLibraryToAFewUlpEverywhere) {
    std::mt19937_64 random(2022);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> exponent(-12.0, 12.0);
    double worst = 0.0;
    for (int k = 0; k < 200000; ++k) {
        const double y = unit(random) * std::pow(10.0, exponent(random));
        const double x = unit(random) * std::pow(10.0, exponent(random));
        const double expected = std::atan2(y, x);
        const double ulp = std::nextafter(std::abs(expected), 4.0) - std::abs(expected);
        worst = std::max(worst, std::abs(detail::atan2(y, x) - expected) / ulp);
    }
    EXPECT_LE(worst, 4.0);
    for (const auto& [y, x] : {std::pair{0.0, -1.0},
                               {-0.0, -1.0},
                               {0.0, 0.0},
                               {-0.0, -0.0},
                               {1.0, 0.0},
                               {-1.0, -0.0},
                               {1.0, 1.0},
                               {-2.0, -2.0}}) {
        EXPECT_EQ(detail::atan2(y, x), std::atan2(y, x)) << y << ", " << x;
    }
    EXPECT_TRUE(std::isnan(detail::atan2(std::nan(""), 1.0)));
    EXPECT_EQ(detail::atan2(1.0, std::numeric_limits<double>::infinity()), 0.0);
}

TEST(Unwrap, ReproducesAnySequenceWithStepsBelowPi) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> step(-3.1, 3.1);
    std::vector<double> sequence{0.4};
    for (int k = 0; k < 2000; ++k) {
        sequence.push_back(sequence.back() + step(random));
    }
    std::vector<double> wrapped;
    for (double x : sequence) {
        wrapped.push_back(geometry::wrapAngle(x));
    }
    const std::vector<double> unwrapped = geometry::unwrap(wrapped);
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        ASSERT_NEAR(unwrapped[i], sequence[i], 1e-9) << i;
    }
}

// A closed convex polygon (irregular, on an ellipse) traversed three times; with chords equal
// to the edges the turning over one period sums to 2 pi and every tau is positive.
TEST(Tangents, ClosedConvexPolygonTurnsTwoPiPerRevolution) {
    std::vector<double> angles{0.0, 0.5, 1.4, 2.0, 2.9, 3.3, 4.4, 5.0, 5.9};
    std::vector<Vec2> points;
    for (int turn = 0; turn < 3; ++turn) {
        for (double a : angles) {
            points.emplace_back(40.0 * std::cos(a), 25.0 * std::sin(a));
        }
    }
    auto field = computeTangents(points, 1.0, 0.0); // l_t = 1 mm < every edge
    ASSERT_TRUE(field.has_value());
    const std::size_t period = angles.size();
    double sum = 0.0;
    for (std::size_t i = period; i < 2 * period; ++i) {
        EXPECT_GT(field->turning[i], 0.0);
        sum += field->turning[i];
    }
    EXPECT_NEAR(sum, 2.0 * kPi, 1e-9);
    EXPECT_NEAR(field->forwardAngle[2 * period] - field->forwardAngle[period], 2.0 * kPi, 1e-9);
}

TEST(Tangents, CircleTurningIsTheChordAngle) {
    const double r = 50.0;
    const std::vector<Vec2> points = testing::regularPolygon(720, r); // 0.436 mm chords
    auto field = computeTangents(points, 2.0, 3.0);
    ASSERT_TRUE(field.has_value());
    // The forward chord spans the first k steps reaching l_t; tau = k dphi = 2 asin(c / 2r).
    const double dphi = 2.0 * kPi / 720.0;
    const double c = (points[5] - points[0]).norm(); // 5 steps: first chord >= 2 mm
    ASSERT_GE(c, 2.0);
    ASSERT_LT((points[4] - points[0]).norm(), 2.0);
    for (std::size_t i = 10; i < 700; i += 37) {
        EXPECT_NEAR(field->turning[i], 5.0 * dphi, 1e-12);
        EXPECT_NEAR(field->turning[i], 2.0 * std::asin(c / (2.0 * r)), 1e-12);
        EXPECT_NEAR(field->turning[i], c / r, 1e-4 * c / r);
        EXPECT_NEAR(field->curvature[i], 1.0 / r, 1e-4 / r);
    }
}

TEST(Tangents, WrappedThenUnwrappedIsWhatComputeTangentsGives) {
    // Three turns of a circle: the wrapped angles jump by 2 pi where the unwrapped ones go on.
    std::vector<Vec2> points;
    for (int i = 0; i < 3 * 360; ++i) {
        const double phi = 2.0 * kPi * i / 360.0;
        points.emplace_back(40.0 * std::cos(phi), 40.0 * std::sin(phi));
    }
    const auto whole = computeTangents(points, 2.0, 3.0);
    auto steps = computeWrappedTangents(points, 2.0, 3.0);
    ASSERT_TRUE(whole.has_value());
    ASSERT_TRUE(steps.has_value());
    for (double angle : steps->forwardAngle) {
        EXPECT_GT(angle, -kPi);
        EXPECT_LE(angle, kPi);
    }
    unwrapForwardAngles(*steps);
    EXPECT_EQ(steps->forwardAngle, whole->forwardAngle);
    EXPECT_EQ(steps->turning, whole->turning);
    EXPECT_EQ(steps->curvature, whole->curvature);
    // Nearly three turns from the first tangent to the last (the last ones take shorter chords).
    EXPECT_GT(whole->forwardAngle.back() - whole->forwardAngle.front(), 5.8 * kPi);
}

TEST(Tangents, DegenerateProjectionIsAnError) {
    const std::vector<Vec2> points(5, Vec2(1.0, 2.0));
    EXPECT_FALSE(computeTangents(points, 0.5, 3.0).has_value());
}

// y = x^3 / 100 in the plane frame, fed along +x: concave for x < 0, convex for x > 0.
std::vector<Vec2> cubicCurve(double noiseMm, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> noise(-noiseMm, noiseMm);
    std::vector<Vec2> points;
    for (int k = -400; k <= 400; ++k) {
        const double x = 0.025 * k;
        points.emplace_back(x + noise(random), x * x * x / 100.0 + noise(random));
    }
    return points;
}

std::vector<std::size_t> alteredPointsOf(const std::vector<Vec2>& points) {
    auto field = computeTangents(points, 0.5, 3.0);
    EXPECT_TRUE(field.has_value());
    std::vector<double> s{0.0};
    for (std::size_t i = 1; i < points.size(); ++i) {
        s.push_back(s.back() + (points[i] - points[i - 1]).norm());
    }
    // Only the hysteresis acts: no merging, no minimum run length.
    const CurvatureSettings settings{2.0, 1e-4, 0.0, 0.0};
    const CurvatureAnalysis analysis =
        analyseCurvature(s, field->curvature, field->turning, settings);
    return alteredPoints(analysis.state);
}

TEST(CurvatureStates, CubicHasOneConcaveToConvexPointAtTheInflection) {
    const std::vector<Vec2> points = cubicCurve(0.0, 1);
    const std::vector<std::size_t> altered = alteredPointsOf(points);
    ASSERT_EQ(altered.size(), 1u);
    EXPECT_NEAR(points[altered[0]].x(), 0.0, 1.0); // within w / 2 of x = 0
}

TEST(CurvatureStates, MicronNoiseDoesNotChangeTheAlteredPointCount) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const std::vector<Vec2> points = cubicCurve(1e-3, seed);
        const std::vector<std::size_t> altered = alteredPointsOf(points);
        ASSERT_EQ(altered.size(), 1u) << "seed " << seed;
        EXPECT_NEAR(points[altered[0]].x(), 0.0, 1.0);
    }
}

TEST(CurvatureStates, ShortRunsAreDroppedAndCloseRunsMerged) {
    // Curvature sign pattern along S (1 mm steps): convex, concave 10, convex 3, concave 10.
    std::vector<double> s(60);
    std::iota(s.begin(), s.end(), 0.0);
    std::vector<double> kappa(60, 0.01);
    for (std::size_t i = 20; i < 30; ++i) {
        kappa[i] = -0.01;
    }
    for (std::size_t i = 33; i < 43; ++i) {
        kappa[i] = -0.01;
    }
    const std::vector<double> tau(60, 0.0);
    const CurvatureAnalysis merged = analyseCurvature(s, kappa, tau, {0.0, 1e-4, 5.0, 0.0});
    ASSERT_EQ(merged.runs.size(), 1u);
    EXPECT_EQ(merged.runs[0].entry, 20u);
    EXPECT_EQ(merged.runs[0].exit, 43u);
    const CurvatureAnalysis dropped = analyseCurvature(s, kappa, tau, {0.0, 1e-4, 2.0, 15.0});
    EXPECT_TRUE(dropped.runs.empty());
}

} // namespace
} // namespace bladeaxis::scheduling

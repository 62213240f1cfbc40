#include "core/base/units.h"
#include "core/blade/offset_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace bladeaxis::blade {
namespace {

Curve2 square(double side) {
    return {Vec2(0, 0), Vec2(side, 0), Vec2(side, side), Vec2(0, side)};
}

// A crescent: outer arc of radius 30 (convex) and inner arc of radius 20 (concave), both
// centred at the origin, spanning 0..120 deg, closed by the two radial ends.
Curve2 crescent() {
    Curve2 curve;
    const int n = 400;
    const double span = units::degToRad(120.0);
    for (int k = 0; k <= n; ++k) {
        const double a = span * k / n;
        curve.emplace_back(30.0 * std::cos(a), 30.0 * std::sin(a));
    }
    for (int k = n; k >= 0; --k) {
        const double a = span * k / n;
        curve.emplace_back(20.0 * std::cos(a), 20.0 * std::sin(a));
    }
    return curve;
}

TEST(OffsetCurve, SquareOffsetIsFourSidesPlusAFullCircle) {
    const Result<OffsetCurve> offset = OffsetCurve::create(square(10.0), 2.0);
    ASSERT_TRUE(offset.has_value());
    EXPECT_NEAR(offset->length(), 40.0 + units::kTwoPi * 2.0, 1e-12);
}

TEST(OffsetCurve, EverySampleIsAtDistanceRFromContactAndPolygon) {
    const Curve2 poly = square(10.0);
    const Result<OffsetCurve> offset = OffsetCurve::create(poly, 2.0);
    ASSERT_TRUE(offset.has_value());
    for (int k = 0; k < 1000; ++k) {
        const OffsetSample s = offset->at(k / 1000.0);
        EXPECT_NEAR((s.centre - s.contact).norm(), 2.0, 1e-12);
        EXPECT_NEAR(distanceToCurve(s.centre, poly), 2.0, 1e-9);
    }
}

TEST(OffsetCurve, StartsAtVertexZeroAndWrapsAround) {
    const Result<OffsetCurve> offset = OffsetCurve::create(square(10.0), 1.0);
    ASSERT_TRUE(offset.has_value());
    const OffsetSample start = offset->at(0.0);
    EXPECT_NEAR((start.contact - Vec2(0, 0)).norm(), 0.0, 1e-12);
    // The arc at vertex 0 starts with the normal of the incoming edge (0,10)->(0,0), i.e. (-1, 0)
    // in (y, z).
    EXPECT_NEAR((start.normal - Vec2(-1, 0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((offset->at(1.25).centre - offset->at(0.25).centre).norm(), 0.0, 1e-12);
}

TEST(OffsetCurve, ConcaveRadiusOfACrescentIsItsInnerRadius) {
    EXPECT_NEAR(minConcaveRadius(crescent()), 20.0, 0.01);
    EXPECT_TRUE(std::isinf(minConcaveRadius(square(3.0))));
}

TEST(OffsetCurve, ConcaveSamplesKeepTheirDistanceBelowTheConcaveRadius) {
    const Curve2 poly = crescent();
    const Result<OffsetCurve> offset = OffsetCurve::create(poly, 8.0);
    ASSERT_TRUE(offset.has_value());
    for (int k = 0; k < 500; ++k) {
        const OffsetSample s = offset->at(k / 500.0);
        EXPECT_NEAR(distanceToCurve(s.centre, poly), 8.0, 1e-9);
    }
}

TEST(OffsetCurve, RadiusAboveTheConcaveRadiusIsRejectedNamingBoth) {
    const Result<OffsetCurve> offset = OffsetCurve::create(crescent(), 25.0);
    ASSERT_FALSE(offset.has_value());
    EXPECT_NE(offset.error().message.find("R = 25"), std::string::npos);
    EXPECT_NE(offset.error().message.find("concave radius of curvature 19.99"), std::string::npos);
}

TEST(OffsetCurve, SamplesNameTheEdgeAndFractionHoldingTheContact) {
    const Curve2 poly = crescent();
    const Result<OffsetCurve> offset = OffsetCurve::create(poly, 8.0);
    ASSERT_TRUE(offset.has_value());
    EXPECT_EQ(offset->vertexCount(), poly.size());
    for (int k = 0; k < 997; ++k) {
        const OffsetSample s = offset->at(k / 997.0);
        ASSERT_LT(s.edge, poly.size());
        ASSERT_GE(s.edgeFraction, 0.0);
        ASSERT_LE(s.edgeFraction, 1.0);
        const Vec2 onEdge = (1.0 - s.edgeFraction) * poly[s.edge] +
                            s.edgeFraction * poly[(s.edge + 1) % poly.size()];
        EXPECT_NEAR((onEdge - s.contact).norm(), 0.0, 1e-9) << k;
    }
}

// On a polygon with concave vertices the sample normal jumps where the centre curve has a
// corner; the blended normal does not, and stays within half a vertex turn of the normal.
TEST(OffsetCurve, BlendedNormalIsContinuousAndNearTheNormal) {
    const Curve2 poly = crescent(); // 0.3 deg per vertex on both arcs
    const Result<OffsetCurve> offset = OffsetCurve::create(poly, 8.0);
    ASSERT_TRUE(offset.has_value());
    const int samples = 200000;
    double largestNormalStep = 0.0;
    Vec2 previous = offset->at(0.0).blendedNormal;
    for (int k = 1; k <= samples; ++k) {
        const OffsetSample s = offset->at(static_cast<double>(k) / samples);
        EXPECT_NEAR(s.blendedNormal.norm(), 1.0, 1e-12);
        const double halfTurn = units::degToRad(0.15) + 1e-9;
        EXPECT_LE(std::acos(std::clamp(s.blendedNormal.dot(s.normal), -1.0, 1.0)), halfTurn) << k;
        // Along the curve (~190 mm) consecutive samples are ~1 um apart.
        ASSERT_LT((s.blendedNormal - previous).norm(), 1e-3) << k;
        largestNormalStep =
            std::max(largestNormalStep,
                     (s.normal - offset->at(static_cast<double>(k - 1) / samples).normal).norm());
        previous = s.blendedNormal;
    }
    EXPECT_GT(largestNormalStep, 4e-3) << "the polygon normal itself jumps";
}

} // namespace
} // namespace bladeaxis::blade

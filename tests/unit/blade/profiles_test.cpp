#include "core/blade/offset_curve.h"
#include "core/blade/profiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bladeaxis::blade {
namespace {

// z of the upper (sign > 0) or lower surface of a unit-chord section at chord fraction x, by
// linear interpolation along the polygon edges that cross x.
double surfaceZ(const Curve2& curve, double x, double sign) {
    double best = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const Vec2& a = curve[i];
        const Vec2& b = curve[(i + 1) % curve.size()];
        if ((a.x() - x) * (b.x() - x) > 0.0 || a.x() == b.x()) {
            continue;
        }
        const double z = a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
        if (std::isnan(best) || sign * z > sign * best) {
            best = z;
        }
    }
    return best;
}

TEST(NacaSection, Naca0012HalfThicknessAtThirtyPercentChordIsSixPercent) {
    // The NACA 4-digit thickness polynomial is scaled so that 0012 has its maximum 0.06c at 0.3c.
    const Result<Curve2> curve = nacaSection(NacaProfile{0.0, 0.0, 0.12}, 200);
    ASSERT_TRUE(curve.has_value());
    EXPECT_NEAR(surfaceZ(*curve, 0.3, 1.0), 0.06, 1e-3);
    EXPECT_NEAR(surfaceZ(*curve, 0.3, -1.0), -0.06, 1e-3);
    EXPECT_NEAR(nacaHalfThickness(0.12, 0.3), 0.06, 1e-4);
}

TEST(NacaSection, Naca2412MeanLineReachesTheCamberAtItsPosition) {
    const NacaProfile profile{0.02, 0.4, 0.12};
    EXPECT_DOUBLE_EQ(nacaCamber(profile, 0.4), 0.02);
    EXPECT_DOUBLE_EQ(nacaCamberSlope(profile, 0.4), 0.0);
    const Result<Curve2> curve = nacaSection(profile, 200);
    ASSERT_TRUE(curve.has_value());
    // At maximum camber the camber line is horizontal, so thickness is applied vertically.
    const double mean = 0.5 * (surfaceZ(*curve, 0.4, 1.0) + surfaceZ(*curve, 0.4, -1.0));
    EXPECT_NEAR(mean, 0.02, 1e-3);
}

TEST(NacaSection, TrailingEdgeIsClosed) {
    EXPECT_NEAR(nacaHalfThickness(0.12, 1.0), 0.0, 1e-12);
    const Result<Curve2> curve = nacaSection(NacaProfile{0.1, 0.45, 0.12}, 50);
    ASSERT_TRUE(curve.has_value());
    EXPECT_NEAR((curve->front() - Vec2(1.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_GT(signedArea(*curve), 0.0);
}

TEST(NacaSection, HighCamberHasAConcavePressureSideAndSymmetricHasNone) {
    const Result<Curve2> cambered = nacaSection(NacaProfile{0.10, 0.45, 0.12}, 200);
    const Result<Curve2> symmetric = nacaSection(NacaProfile{0.0, 0.0, 0.12}, 200);
    ASSERT_TRUE(cambered.has_value());
    ASSERT_TRUE(symmetric.has_value());
    EXPECT_TRUE(std::isfinite(minConcaveRadius(*cambered)));
    EXPECT_TRUE(std::isinf(minConcaveRadius(*symmetric)));
}

TEST(NacaSection, RejectsCamberOutsideItsRange) {
    const Result<Curve2> curve = nacaSection(NacaProfile{0.3, 0.4, 0.12}, 50);
    ASSERT_FALSE(curve.has_value());
    EXPECT_NE(curve.error().message.find("camber m = 0.3"), std::string::npos);
}

TEST(TurbineSection, PressureSideIsConcaveWithinTheCamberArcRadius) {
    // A 90 deg circular-arc camber over a unit chord has radius 1 / (2 sin 45 deg); the pressure
    // side lies inside the arc, so its concave radius is smaller but still positive.
    TurbineProfile profile;
    profile.turning = std::numbers::pi / 2.0;
    const Result<Curve2> curve = turbineSection(profile, 200);
    ASSERT_TRUE(curve.has_value());
    EXPECT_GT(signedArea(*curve), 0.0);
    const double concave = minConcaveRadius(*curve);
    EXPECT_LT(concave, 1.0 / (2.0 * std::sin(std::numbers::pi / 4.0)));
    EXPECT_GT(concave, 0.3);
}

TEST(TurbineSection, LeadingEdgeCircleHasTheRequestedRadius) {
    TurbineProfile profile;
    profile.leRadius = 0.025;
    const Result<Curve2> curve = turbineSection(profile, 100);
    ASSERT_TRUE(curve.has_value());
    // The leading-edge circle is centred on the camber-line start (0, 0): no point is closer.
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec2& p : *curve) {
        nearest = std::min(nearest, p.norm());
    }
    EXPECT_NEAR(nearest, 0.025, 1e-9);
}

TEST(TurbineSection, RejectsEdgeRadiusLargerThanHalfThickness) {
    TurbineProfile profile;
    profile.maxThickness = 0.1;
    profile.leRadius = 0.08;
    const Result<Curve2> curve = turbineSection(profile, 50);
    ASSERT_FALSE(curve.has_value());
    EXPECT_NE(curve.error().message.find("leading-edge radius"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::blade

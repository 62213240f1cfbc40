#include "core/base/units.h"
#include "core/blade/blade.h"
#include "core/blade/presets.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::blade {
namespace {

using units::degToRad;

BladeSpec symmetricSpec() {
    BladeSpec spec;
    spec.profile = NacaProfile{0.0, 0.0, 0.12};
    spec.spanStart = 0.0;
    spec.spanEnd = 60.0;
    spec.chordStart = 80.0;
    spec.chordEnd = 60.0;
    spec.staggerStart = degToRad(20.0);
    spec.staggerEnd = degToRad(35.0);
    spec.pointsPerSide = 200;
    return spec;
}

// Angle of the line through the two section points farthest apart (leading and trailing edge).
double chordAngle(const Curve2& curve) {
    Vec2 side;
    const std::size_t phase = phaseIndex(curve, Vec2(0, 1), &side);
    (void)phase;
    // The chord is perpendicular to the side normal.
    return std::atan2(-side.x(), side.y());
}

TEST(Blade, SectionsHaveTheirAreaCentroidOnTheAxis) {
    const Result<Blade> blade = demoBlade();
    ASSERT_TRUE(blade.has_value());
    for (double x : {0.0, 7.0, 20.0}) {
        EXPECT_NEAR(areaCentroid(blade->sectionAt(x)).norm(), 0.0, 1e-9) << "x = " << x;
    }
}

TEST(Blade, LeanAndBowMoveTheCentroidAlongTheStackingLine) {
    BladeSpec spec = symmetricSpec();
    spec.leanMm = 1.5;
    spec.bowMm = -1.0;
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_TRUE(blade.has_value());
    EXPECT_NEAR((areaCentroid(blade->sectionAt(60.0)) - Vec2(1.5, 0.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((areaCentroid(blade->sectionAt(30.0)) - Vec2(0.75, -1.0)).norm(), 0.0, 1e-9);
}

TEST(Blade, StaggerFollowsTheLinearTwist) {
    const Result<Blade> blade = Blade::create(symmetricSpec());
    ASSERT_TRUE(blade.has_value());
    // The chord line of a symmetric section joins its leading and trailing edge exactly.
    for (double x : {0.0, 30.0, 60.0}) {
        const double expected = degToRad(20.0 + 15.0 * x / 60.0);
        const double angle =
            std::remainder(chordAngle(blade->sectionAt(x)) - expected, std::numbers::pi);
        EXPECT_NEAR(angle, 0.0, 1e-6) << "x = " << x;
    }
}

TEST(Blade, ChordTaperScalesThePerimeter) {
    const Result<Blade> blade = Blade::create(symmetricSpec());
    ASSERT_TRUE(blade.has_value());
    EXPECT_NEAR(perimeter(blade->sectionAt(60.0)) / perimeter(blade->sectionAt(0.0)), 60.0 / 80.0,
                1e-12);
    EXPECT_NEAR(perimeter(blade->sectionAt(30.0)) / perimeter(blade->sectionAt(0.0)), 70.0 / 80.0,
                1e-12);
}

TEST(Blade, PhaseVertexIsOnTheSuctionSide) {
    BladeSpec spec = demoBladeSpec();
    spec.staggerStart = 0.0;
    spec.staggerEnd = 0.0;
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_TRUE(blade.has_value());
    const Curve2 section = blade->sectionAt(0.0);
    // With zero stagger the suction side is the upper (+z) side, the farthest from the chord
    // line (LE-TE, nearly horizontal here): vertex 0 is at (or very near) the highest point.
    double highest = -1e9;
    for (const Vec2& p : section) {
        highest = std::max(highest, p.y());
    }
    EXPECT_GT(section.front().y(), 0.95 * highest);
}

TEST(Blade, RejectsLeanBeyondTwoMillimetres) {
    BladeSpec spec = symmetricSpec();
    spec.leanMm = 3.0;
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_FALSE(blade.has_value());
    EXPECT_NE(blade.error().message.find("lean (mm) = 3"), std::string::npos);
}

// A point table of two square stations, 10 mm at x = 0 growing to 20 mm at x = 10.
BladeSpec squareTableSpec() {
    SectionTable table;
    table.stations.push_back({0.0, {Vec2(0, 0), Vec2(10, 0), Vec2(10, 10), Vec2(0, 10)}, 0});
    table.stations.push_back({10.0, {Vec2(0, 0), Vec2(20, 0), Vec2(20, 20), Vec2(0, 20)}, 0});
    BladeSpec spec;
    spec.profile = table;
    spec.pointsPerSide = 50;
    return spec;
}

TEST(Blade, TableSectionsInterpolateBetweenStations) {
    const Result<Blade> blade = Blade::create(squareTableSpec());
    ASSERT_TRUE(blade.has_value());
    EXPECT_DOUBLE_EQ(blade->spanStart(), 0.0);
    EXPECT_DOUBLE_EQ(blade->spanEnd(), 10.0);
    // Corresponding points of similar squares: the mid section is the 15 mm square.
    EXPECT_NEAR(perimeter(blade->sectionAt(5.0)), 60.0, 1e-9);
    EXPECT_NEAR(signedArea(blade->sectionAt(5.0)), 225.0, 1e-9);
}

// Central differences of the sections themselves are the independent reference: every vertex
// of sectionAt(x) is the same material point of the blade at every x.
TEST(Blade, SectionVelocityIsTheSpanWiseDerivativeOfTheSections) {
    BladeSpec spec = symmetricSpec();
    spec.profile = NacaProfile{0.08, 0.4, 0.12};
    spec.staggerBow = degToRad(3.0);
    spec.leanMm = 1.5;
    spec.bowMm = -1.0;
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_TRUE(blade.has_value());
    const double h = 1e-4;
    for (double x : {1.0, 17.0, 30.0, 59.0}) {
        const Curve2 before = blade->sectionAt(x - h);
        const Curve2 after = blade->sectionAt(x + h);
        for (std::size_t i = 0; i < before.size(); i += 37) {
            const Vec2 expected = (after[i] - before[i]) / (2.0 * h);
            EXPECT_NEAR((blade->sectionVelocity(x, i) - expected).norm(), 0.0, 1e-6)
                << "x = " << x << ", vertex " << i;
        }
    }
}

TEST(Blade, TableSectionVelocityIsConstantBetweenStations) {
    const Result<Blade> blade = Blade::create(squareTableSpec());
    ASSERT_TRUE(blade.has_value());
    const Curve2 first = blade->sectionAt(0.0);
    const Curve2 last = blade->sectionAt(10.0);
    for (std::size_t i = 0; i < first.size(); i += 7) {
        const Vec2 expected = (last[i] - first[i]) / 10.0;
        EXPECT_NEAR((blade->sectionVelocity(3.0, i) - expected).norm(), 0.0, 1e-12) << i;
        EXPECT_NEAR((blade->sectionVelocity(12.0, i) - expected).norm(), 0.0, 1e-12) << i;
    }
}

} // namespace
} // namespace bladeaxis::blade

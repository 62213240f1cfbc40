#include "core/base/units.h"
#include "core/blade/helical_path.h"
#include "core/blade/offset_curve.h"
#include "core/blade/presets.h"
#include "tests/unit/blade/blade_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace bladeaxis::blade {
namespace {

using testing::distanceToBlade;
using units::degToRad;

HelicalPathSpec shortDemoPath() {
    HelicalPathSpec spec = demoPathSpec();
    spec.revolutions = 3;
    return spec;
}

const Blade& demo() {
    static const Blade blade = *demoBlade();
    return blade;
}

const GeneratedPath& demoPath() {
    static const GeneratedPath path = *generateHelicalPath(demo(), shortDemoPath());
    return path;
}

// Polar angle of the tool axis projected on the (y, z) plane: the traversal is
// counter-clockwise in (y, z), so this angle grows by 2 pi per revolution.
std::vector<double> unwrappedAxisAngle(const GeneratedPath& path) {
    std::vector<double> angles;
    double previous = 0.0;
    for (const toolpath::ClRecord& record : path.path.records) {
        double a = std::atan2(record.axis.z(), record.axis.y());
        if (!angles.empty()) {
            a = previous + std::remainder(a - previous, units::kTwoPi);
        }
        angles.push_back(a);
        previous = a;
    }
    return angles;
}

TEST(HelicalPath, APathOfMoreThanTenMillionPointsIsRefusedAfterItsFirstRevolution) {
    auto bladeModel = Blade::create(demoBladeSpec());
    ASSERT_TRUE(bladeModel.has_value());
    HelicalPathSpec spec = demoPathSpec();
    spec.revolutions = 10000;
    spec.pitch = 0.0015; // 10,000 revolutions within the blade's span
    spec.chordalTolerance = 1e-4;
    const auto path = generateHelicalPath(*bladeModel, spec);
    ASSERT_FALSE(path.has_value());
    EXPECT_EQ(path.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(path.error().message.find("more than the 10000000 a generated program may have"),
              std::string::npos)
        << path.error().toString();
}

TEST(HelicalPath, ContactsLieOnTheSectionsAndCentresOnTheSurfaceNormal) {
    const GeneratedPath& path = demoPath();
    const double radius = 8.0;
    ASSERT_EQ(path.path.records.size(), path.centre.size());
    for (std::size_t i = 0; i < path.centre.size(); ++i) {
        const toolpath::ClRecord& record = path.path.records[i];
        EXPECT_DOUBLE_EQ(path.contact[i].x(), path.sectionX[i]);
        EXPECT_NEAR(distanceToCurve(path.contact[i].tail<2>(), demo().sectionAt(path.sectionX[i])),
                    0.0, 1e-9);
        EXPECT_NEAR(path.normal[i].norm(), 1.0, 1e-12);
        EXPECT_NEAR((path.centre[i] - path.contact[i] - radius * path.normal[i]).norm(), 0.0, 1e-9);
        EXPECT_LT((record.tip + radius * record.axis - path.centre[i]).norm(), 1e-9);
    }
}

// The ball touches the blade and stays out of it: the nearest surface point of every centre is
// R away. The twist tilts the surface normal out of the section plane (by up to ~14 deg here),
// so the centres leave the planes x = sectionX.
TEST(HelicalPath, BallCentresAreTheToolRadiusAwayFromTheTwistedBlade) {
    const GeneratedPath& path = demoPath();
    double largestTilt = 0.0;
    for (std::size_t i = 0; i < path.centre.size(); i += 5) {
        EXPECT_NEAR(distanceToBlade(demo(), path.centre[i]), 8.0, 2e-3) << "record " << i;
        largestTilt = std::max(largestTilt, std::abs(path.normal[i].x()));
    }
    EXPECT_GT(largestTilt, 0.1);
}

TEST(HelicalPath, ChordMidpointsStayWithinTheChordalTolerance) {
    const GeneratedPath& path = demoPath();
    const double tolerance = shortDemoPath().chordalTolerance;
    for (std::size_t i = 0; i + 1 < path.centre.size(); ++i) {
        EXPECT_LE((path.centre[i + 1] - path.centre[i]).norm(), shortDemoPath().maxStep + 1e-12);
    }
    for (std::size_t i = 0; i + 1 < path.centre.size(); i += 7) {
        const Vec3 mid = 0.5 * (path.centre[i] + path.centre[i + 1]);
        EXPECT_NEAR(distanceToBlade(demo(), mid), 8.0, tolerance + 2e-3) << "record " << i;
    }
}

TEST(HelicalPath, PointsAreDenseAtTheEdges) {
    const GeneratedPath& path = demoPath();
    double shortest = 1e9;
    double longest = 0.0;
    for (std::size_t i = 0; i + 1 < path.centre.size(); ++i) {
        const double chord = (path.centre[i + 1] - path.centre[i]).norm();
        shortest = std::min(shortest, chord);
        longest = std::max(longest, chord);
    }
    // Around the trailing edge the centre runs on an arc of radius R = 8 mm: a 0.01 mm sagitta
    // allows chords of 2 sqrt(2 R tol) = 0.8 mm; on the flat sides the 1 mm max step governs.
    EXPECT_LT(shortest, 0.81);
    EXPECT_GT(longest, 0.95);
}

TEST(HelicalPath, RevolutionsAxialAdvanceAndConstantTilt) {
    const GeneratedPath& path = demoPath();
    const HelicalPathSpec spec = shortDemoPath();
    const std::set<int> revolutions(path.revolution.begin(), path.revolution.end());
    EXPECT_EQ(revolutions, (std::set<int>{0, 1, 2}));
    EXPECT_DOUBLE_EQ(path.parameter.front(), 0.0);
    EXPECT_DOUBLE_EQ(path.parameter.back(), 3.0);
    EXPECT_NEAR(path.sectionX.back() - path.sectionX.front(), 3.0 * spec.pitch, 1e-12);
    for (const toolpath::ClRecord& record : path.path.records) {
        EXPECT_NEAR(record.axis.x(), std::sin(degToRad(5.0)), 1e-15);
        EXPECT_NEAR(record.axis.norm(), 1.0, 1e-12);
        EXPECT_DOUBLE_EQ(record.feed, 50.0);
        EXPECT_EQ(record.motion, toolpath::MotionKind::Feed);
    }
    // Closed revolutions: the first records of consecutive revolutions sit above each other.
    const auto second = std::find(path.revolution.begin(), path.revolution.end(), 1);
    const std::size_t i = static_cast<std::size_t>(second - path.revolution.begin());
    EXPECT_NEAR(path.contact[i].x() - path.contact[0].x(), spec.pitch, 1e-12);
}

TEST(HelicalPath, LeadTiltsTheAxisTowardsTheFeedDirection) {
    const GeneratedPath& path = demoPath();
    for (std::size_t i = 0; i < path.normal.size(); ++i) {
        const Vec3& v = path.path.records[i].axis;
        const Vec3& n = path.normal[i];
        // Angle about +x from the normal's azimuth to the axis, counter-clockwise (= the feed
        // sense).
        const double angle =
            std::atan2(n.y() * v.z() - n.z() * v.y(), n.y() * v.y() + n.z() * v.z());
        EXPECT_NEAR(angle, degToRad(15.0), 1e-12);
    }
}

TEST(HelicalPath, OriginalOrientationReciprocatesOnHighCamber) {
    const GeneratedPath& path = demoPath();
    const std::vector<double> angle = unwrappedAxisAngle(path);
    // Independent expectation: within a revolution the axis turns back by the total concave
    // turning of the section (the normal follows the pressure side backwards).
    const Curve2 section = demo().sectionAt(path.sectionX[0] + 1.0);
    double concaveTurning = 0.0;
    for (std::size_t k = 0; k < section.size(); ++k) {
        const Vec2 in = section[k] - section[(k + section.size() - 1) % section.size()];
        const Vec2 out = section[(k + 1) % section.size()] - section[k];
        const double turn = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
        concaveTurning += std::min(turn, 0.0);
    }
    ASSERT_LT(concaveTurning, degToRad(-5.0));
    double backwards = 0.0;
    int reversals = 0;
    bool increasing = true;
    for (std::size_t i = 0; i + 1 < angle.size(); ++i) {
        const double step = angle[i + 1] - angle[i];
        if (path.revolution[i] == 1 && step < 0.0) {
            backwards += step;
        }
        if (std::abs(step) > 1e-6 && (step > 0.0) != increasing) {
            increasing = step > 0.0;
            ++reversals;
        }
    }
    EXPECT_NEAR(backwards, concaveTurning, degToRad(0.5));
    EXPECT_GE(reversals, 2 * 3);
    // Net: three turns plus the twist between the first and last section (10 deg per 20 mm,
    // 3 x 2 mm of advance), since both records sit at the phase vertex.
    EXPECT_NEAR(angle.back() - angle.front(), 3.0 * units::kTwoPi + degToRad(3.0), 1e-9);
}

TEST(HelicalPath, SymmetricSectionHasNoReversal) {
    BladeSpec blade = demoBladeSpec();
    blade.profile = NacaProfile{0.0, 0.0, 0.12};
    const Result<Blade> symmetric = Blade::create(blade);
    ASSERT_TRUE(symmetric.has_value());
    const Result<GeneratedPath> path = generateHelicalPath(*symmetric, shortDemoPath());
    ASSERT_TRUE(path.has_value()) << path.error().toString();
    EXPECT_TRUE(std::isinf(path->minConcaveRadius));
    const std::vector<double> angle = unwrappedAxisAngle(*path);
    for (std::size_t i = 0; i + 1 < angle.size(); ++i) {
        EXPECT_GE(angle[i + 1] - angle[i], -1e-9) << "record " << i;
    }
}

TEST(HelicalPath, SameSeedGivesIdenticalOutputAndNoiseDependsOnTheSeed) {
    HelicalPathSpec spec = shortDemoPath();
    spec.revolutions = 1;
    spec.leadNoise = degToRad(0.2);
    const Result<GeneratedPath> a = generateHelicalPath(demo(), spec);
    const Result<GeneratedPath> b = generateHelicalPath(demo(), spec);
    spec.seed = 2;
    const Result<GeneratedPath> c = generateHelicalPath(demo(), spec);
    ASSERT_TRUE(a && b && c);
    ASSERT_EQ(a->path.records.size(), b->path.records.size());
    ASSERT_EQ(a->path.records.size(), c->path.records.size());
    bool differs = false;
    for (std::size_t i = 0; i < a->path.records.size(); ++i) {
        EXPECT_EQ(a->path.records[i].tip, b->path.records[i].tip);
        EXPECT_EQ(a->path.records[i].axis, b->path.records[i].axis);
        differs = differs || a->path.records[i].axis != c->path.records[i].axis;
        EXPECT_EQ(a->centre[i], c->centre[i]); // noise changes the orientation only
    }
    EXPECT_TRUE(differs);
}

TEST(HelicalPath, RoundedTipsLieOnTheMicrometreGrid) {
    HelicalPathSpec spec = shortDemoPath();
    spec.revolutions = 1;
    spec.roundTipTo = 1e-3;
    const Result<GeneratedPath> path = generateHelicalPath(demo(), spec);
    ASSERT_TRUE(path.has_value());
    for (std::size_t i = 0; i < path->path.records.size(); ++i) {
        const Vec3& tip = path->path.records[i].tip;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(tip[k] * 1e3, std::round(tip[k] * 1e3), 1e-6);
        }
        const Vec3 exact = path->centre[i] - 8.0 * path->path.records[i].axis;
        EXPECT_LE((tip - exact).cwiseAbs().maxCoeff(), 0.5e-3 + 1e-12);
    }
}

TEST(HelicalPath, ToolRadiusAboveTheConcaveRadiusIsAClearError) {
    BladeSpec spec = demoBladeSpec();
    TurbineProfile profile;
    profile.turning = degToRad(110.0);
    spec.profile = profile;
    spec.chordStart = spec.chordEnd = 20.0; // concave radius below 20 / (2 sin 55 deg) = 12.2 mm
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_TRUE(blade.has_value());
    HelicalPathSpec path = shortDemoPath();
    path.toolRadius = 12.5;
    const Result<GeneratedPath> generated = generateHelicalPath(*blade, path);
    ASSERT_FALSE(generated.has_value());
    EXPECT_EQ(generated.error().code, ErrorCode::Geometry);
    EXPECT_NE(generated.error().message.find("R = 12.5 mm"), std::string::npos);
    EXPECT_NE(generated.error().message.find("minimum concave radius of curvature"),
              std::string::npos);
}

TEST(HelicalPath, InvalidParametersAreRejectedNamingTheQuantity) {
    HelicalPathSpec spec = shortDemoPath();
    spec.chordalTolerance = 0.0;
    Result<GeneratedPath> path = generateHelicalPath(demo(), spec);
    ASSERT_FALSE(path.has_value());
    EXPECT_NE(path.error().message.find("chordal tolerance"), std::string::npos);
    spec = shortDemoPath();
    spec.revolutions = 20; // 2 + 20 x 2 mm leaves the 20 mm span
    path = generateHelicalPath(demo(), spec);
    ASSERT_FALSE(path.has_value());
    EXPECT_NE(path.error().message.find("leaves the blade span"), std::string::npos);
}

TEST(SyntheticFamily, MembersAreVariedFeasibleAndDeterministic) {
    const Result<std::vector<FamilyMember>> family = syntheticFamily(11, 5);
    const Result<std::vector<FamilyMember>> again = syntheticFamily(11, 5);
    ASSERT_TRUE(family && again);
    ASSERT_EQ(family->size(), 5u);
    for (std::size_t i = 0; i < family->size(); ++i) {
        const FamilyMember& member = (*family)[i];
        EXPECT_EQ(member.name, (*again)[i].name);
        EXPECT_LT(member.path.toolRadius, member.minConcaveRadius);
        const Result<Blade> blade = Blade::create(member.blade);
        ASSERT_TRUE(blade.has_value()) << member.name;
        const Result<GeneratedPath> path = generateHelicalPath(*blade, member.path);
        ASSERT_TRUE(path.has_value()) << member.name << ": " << path.error().toString();
        EXPECT_EQ(path->revolution.back(), member.path.revolutions - 1);
    }
    EXPECT_TRUE(std::any_of(family->begin(), family->end(), [](const FamilyMember& m) {
        return m.name.find("naca-0-") != std::string::npos;
    }));
    EXPECT_TRUE(std::any_of(family->begin(), family->end(), [](const FamilyMember& m) {
        return m.name.find("turbine") != std::string::npos;
    }));
}

} // namespace
} // namespace bladeaxis::blade

#include "core/base/execution.h"
#include "core/blade/closed_curve.h"
#include "core/cad/cad_files.h"
#include "core/cad/sections.h"
#include "tests/unit/cad/cad_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <vector>

namespace bladeaxis::cad {
namespace {

using testing::cadData;
using testing::demoBlade;
using testing::demoSurface;

blade::Curve2 inSectionPlane(const Polyline3& polyline) {
    blade::Curve2 curve;
    for (const Vec3& p : polyline.points) {
        curve.emplace_back(p.y(), p.z());
    }
    return curve;
}

// Largest distance from a vertex of either curve to the other curve (a discrete Hausdorff
// distance; both curves are dense).
double hausdorff(const blade::Curve2& a, const blade::Curve2& b) {
    double worst = 0.0;
    for (const Vec2& p : a) {
        worst = std::max(worst, blade::distanceToCurve(p, b));
    }
    for (const Vec2& p : b) {
        worst = std::max(worst, blade::distanceToCurve(p, a));
    }
    return worst;
}

// The analytic sections are 800-gons from the generator; the surface interpolates them at the
// stations (every mm) and the plane cut is discretised to 2 um. Between the stations the
// surface follows the twist by cubic interpolation.
TEST(Sections, OfTheDemoSurfaceMatchTheGeneratorsSectionsWithinTenMicrons) {
    for (double x : {0.4, 5.0, 7.3, 12.55, 19.6}) {
        const Result<std::vector<Polyline3>> cut = sectionAtX(demoSurface(), x);
        ASSERT_TRUE(cut.has_value()) << cut.error().toString();
        ASSERT_EQ(cut->size(), 1u) << "x = " << x;
        const Polyline3& section = cut->front();
        EXPECT_TRUE(section.closed) << "x = " << x;
        for (const Vec3& p : section.points) {
            ASSERT_NEAR(p.x(), x, 1e-6);
        }
        const blade::Curve2 curve = inSectionPlane(section);
        EXPECT_GT(blade::signedArea(curve), 0.0) << "counter-clockwise in (y, z)";
        const double error = hausdorff(curve, demoBlade().sectionAt(x));
        EXPECT_LT(error, 0.01) << "x = " << x;
        RecordProperty("hausdorff_um_at_" + std::to_string(static_cast<int>(x * 100)),
                       static_cast<int>(error * 1e3));
    }
}

// The direct surface-plane intersection and OpenCASCADE's boolean section agree.
TEST(Sections, FastPathAgreesWithTheBooleanSection) {
    const double x = 11.1;
    const auto fast = sectionAtX(demoSurface(), x);
    const auto reference = sectionAtX(demoSurface(), x, {.booleanOnly = true});
    ASSERT_TRUE(fast.has_value() && reference.has_value());
    ASSERT_EQ(fast->size(), 1u);
    ASSERT_EQ(reference->size(), 1u);
    EXPECT_TRUE(reference->front().closed);
    EXPECT_LT(hausdorff(inSectionPlane(fast->front()), inSectionPlane(reference->front())), 0.005);
}

// The section of an imported model follows the placement: a blade written to IGES and read
// back turned by 90 deg about the rotary axis and shifted along it has the turned section.
TEST(Sections, OfAPlacedImportFollowThePlacement) {
    const std::filesystem::path file = testing::scratchDir() / "blade.igs";
    ASSERT_TRUE(writeCadFile(demoSurface(), file, CadFormat::Iges).has_value());
    Placement placement;
    placement.rotation = rotationX(std::numbers::pi / 2);
    placement.translation = Vec3(3.0, 0.0, 0.0);
    const Result<CadShape> placed = readCadFile(file, placement);
    ASSERT_TRUE(placed.has_value()) << placed.error().toString();
    const Result<std::vector<Polyline3>> cut = sectionAtX(*placed, 7.3 + 3.0);
    ASSERT_TRUE(cut.has_value()) << cut.error().toString();
    ASSERT_EQ(cut->size(), 1u);
    blade::Curve2 expected;
    for (const Vec2& p : demoBlade().sectionAt(7.3)) {
        expected.emplace_back(-p.y(), p.x()); // (y, z) -> (-z, y)
    }
    EXPECT_LT(hausdorff(inSectionPlane(cut->front()), expected), 0.01);
}

TEST(Sections, AreEmptyWhereThePlaneMissesTheShape) {
    const Result<std::vector<Polyline3>> cut = sectionAtX(demoSurface(), 25.0);
    ASSERT_TRUE(cut.has_value()) << cut.error().toString();
    EXPECT_TRUE(cut->empty());
}

TEST(Sections, OfASolidBoxAreItsRectangle) {
    const Result<CadShape> box = readCadFile(cadData("box_solid_inch.step"));
    ASSERT_TRUE(box.has_value()) << box.error().toString();
    const Result<std::vector<Polyline3>> cut = sectionAtX(*box, 6.0);
    ASSERT_TRUE(cut.has_value()) << cut.error().toString();
    ASSERT_EQ(cut->size(), 1u);
    const blade::Curve2 rectangle = inSectionPlane(cut->front());
    EXPECT_TRUE(cut->front().closed);
    EXPECT_NEAR(blade::signedArea(rectangle), 20.0 * 30.0, 1e-6);
    EXPECT_NEAR(blade::perimeter(rectangle), 2 * (20.0 + 30.0), 1e-6);
}

TEST(Sections, InParallelEqualTheSerialOnes) {
    const std::vector<double> xs{1.0, 3.5, 9.0, 14.25, 18.0};
    const auto serial = sectionsAtX(demoSurface(), xs);
    const ThreadCountScope two(2);
    const auto parallel = sectionsAtX(demoSurface(), xs);
    ASSERT_TRUE(serial.has_value() && parallel.has_value());
    ASSERT_EQ(serial->size(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        ASSERT_EQ((*serial)[i].size(), (*parallel)[i].size());
        ASSERT_EQ((*serial)[i][0].points.size(), (*parallel)[i][0].points.size());
        EXPECT_EQ((*serial)[i][0].points, (*parallel)[i][0].points);
    }
}

TEST(Sections, OfTrimmedFacesInParallelEqualTheSerialOnes) {
    const Result<CadShape> box = readCadFile(cadData("box_solid_inch.step"));
    ASSERT_TRUE(box.has_value()) << box.error().toString();
    const std::vector<double> xs{1.5, 3.0, 5.0, 7.0, 9.0, 10.5};
    const auto serial = sectionsAtX(*box, xs);
    const ThreadCountScope two(2);
    const auto parallel = sectionsAtX(*box, xs);
    ASSERT_TRUE(serial.has_value() && parallel.has_value());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        ASSERT_EQ((*parallel)[i].size(), 1u);
        EXPECT_NEAR(blade::signedArea(inSectionPlane((*parallel)[i][0])), 600.0, 1e-6);
        EXPECT_EQ((*serial)[i][0].points, (*parallel)[i][0].points);
    }
}

TEST(Sections, RefuseBadArguments) {
    EXPECT_EQ(sectionAtX(CadShape(), 1.0).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(sectionAtX(demoSurface(), std::nan("")).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(sectionAtX(demoSurface(), 1.0, {.deflection = 0.0}).error().code,
              ErrorCode::InvalidArgument);
}

} // namespace
} // namespace bladeaxis::cad

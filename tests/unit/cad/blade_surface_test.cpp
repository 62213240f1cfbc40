#include "core/blade/presets.h"
#include "core/blade/section_table.h"
#include "core/cad/blade_surface.h"
#include "tests/unit/cad/cad_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace bladeaxis::cad {
namespace {

using testing::demoBlade;
using testing::demoSurface;

// The extent of the analytic sections over the span, sampled densely.
BoundingBox sectionExtent(const blade::Blade& blade) {
    BoundingBox box{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
    for (int j = 0; j <= 40; ++j) {
        const double x = blade.spanStart() + (blade.spanEnd() - blade.spanStart()) * j / 40.0;
        for (const Vec2& p : blade.sectionAt(x)) {
            const Vec3 q(x, p.x(), p.y());
            box.min = box.min.cwiseMin(q);
            box.max = box.max.cwiseMax(q);
        }
    }
    return box;
}

TEST(BladeSurface, IsOneFaceSpanningTheSectionsOfTheBlade) {
    ASSERT_FALSE(demoSurface().isNull());
    EXPECT_EQ(demoSurface().faceCount(), 1);
    const BoundingBox expected = sectionExtent(demoBlade());
    const BoundingBox box = demoSurface().bounds();
    // OCCT's box may be enlarged by the face tolerance and the pole hull; it must still hug the
    // sections within a small fraction of a millimetre.
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(box.min[k], expected.min[k] + 1e-6) << k;
        EXPECT_GE(box.max[k], expected.max[k] - 1e-6) << k;
        EXPECT_NEAR(box.min[k], expected.min[k], 0.05) << k;
        EXPECT_NEAR(box.max[k], expected.max[k], 0.05) << k;
    }
}

TEST(BladeSurface, BuildsPointTableBlades) {
    Result<blade::SectionTable> table = blade::readSectionTableFile(
        std::filesystem::path(BLADEAXIS_TEST_DATA_DIR) / "blade" / "naca0015_three_stations.txt");
    ASSERT_TRUE(table.has_value()) << table.error().toString();
    blade::BladeSpec spec;
    spec.profile = *table;
    const Result<blade::Blade> blade = blade::Blade::create(spec);
    ASSERT_TRUE(blade.has_value()) << blade.error().toString();
    const Result<CadShape> shape = makeBladeSurface(*blade);
    ASSERT_TRUE(shape.has_value()) << shape.error().toString();
    const BoundingBox expected = sectionExtent(*blade);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(shape->bounds().min[k], expected.min[k], 0.05) << k;
        EXPECT_NEAR(shape->bounds().max[k], expected.max[k], 0.05) << k;
    }
}

TEST(BladeSurface, BuildsTurbineProfiles) {
    blade::BladeSpec spec = blade::demoBladeSpec();
    spec.profile = blade::TurbineProfile{};
    spec.spanEnd = 12.0;
    const Result<blade::Blade> turbine = blade::Blade::create(spec);
    ASSERT_TRUE(turbine.has_value()) << turbine.error().toString();
    const Result<CadShape> shape = makeBladeSurface(*turbine, {.stations = 5});
    ASSERT_TRUE(shape.has_value()) << shape.error().toString();
    EXPECT_EQ(shape->faceCount(), 1);
    EXPECT_NEAR(shape->bounds().max.x(), 12.0, 1e-3);
}

TEST(BladeSurface, RefusesTooFewStations) {
    const Result<CadShape> shape = makeBladeSurface(demoBlade(), {.stations = 3});
    ASSERT_FALSE(shape.has_value());
    EXPECT_EQ(shape.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(shape.error().message.find("stations"), std::string::npos);
    const Result<CadShape> spacing = makeBladeSurface(demoBlade(), {.stationSpacing = 0.0});
    ASSERT_FALSE(spacing.has_value());
    EXPECT_EQ(spacing.error().code, ErrorCode::InvalidArgument);
}

} // namespace
} // namespace bladeaxis::cad

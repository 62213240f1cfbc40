#include "core/blade/closed_curve.h"
#include "core/cad/cad_files.h"
#include "core/cad/tessellation.h"
#include "tests/unit/cad/cad_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bladeaxis::cad {
namespace {

using testing::cadData;
using testing::demoBlade;
using testing::demoSurface;

Vec3 corner(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t, int k) {
    return mesh.vertices[t[static_cast<std::size_t>(k)]];
}

// Inside test by the winding number of a closed polygon.
bool insidePolygon(const Vec2& p, const blade::Curve2& polygon) {
    double winding = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 a = polygon[i] - p;
        const Vec2 b = polygon[(i + 1) % polygon.size()] - p;
        winding += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
    return std::abs(winding) > std::numbers::pi;
}

TEST(Tessellation, OfABoxIsClosedAndFacesOutwards) {
    const Result<CadShape> box = readCadFile(cadData("box_solid_inch.step"));
    ASSERT_TRUE(box.has_value()) << box.error().toString();
    const Result<TriangleMesh> mesh = tessellate(*box);
    ASSERT_TRUE(mesh.has_value()) << mesh.error().toString();
    double area = 0.0;
    double volume = 0.0; // divergence theorem: positive only if every normal points outwards
    for (const auto& t : mesh->triangles) {
        const Vec3 a = corner(*mesh, t, 0), b = corner(*mesh, t, 1), c = corner(*mesh, t, 2);
        area += 0.5 * (b - a).cross(c - a).norm();
        volume += a.dot(b.cross(c)) / 6.0;
    }
    EXPECT_NEAR(area, 2 * (10 * 20 + 20 * 30 + 10 * 30), 1e-6);
    EXPECT_NEAR(volume, 10 * 20 * 30, 1e-6);
}

// Vertices lie on the surface, which follows the generator's sections within a few microns;
// triangle centroids stay within the linear deflection; normals point out of the blade.
TEST(Tessellation, OfTheDemoSurfaceHugsTheBladeAndFacesOutwards) {
    const MeshOptions options{.linearDeflection = 0.01, .angularDeflection = 0.3};
    const Result<TriangleMesh> mesh = tessellate(demoSurface(), options);
    ASSERT_TRUE(mesh.has_value()) << mesh.error().toString();
    ASSERT_GT(mesh->triangles.size(), 100u);
    for (std::size_t i = 0; i < mesh->vertices.size(); i += 7) {
        const Vec3& v = mesh->vertices[i];
        ASSERT_LT(blade::distanceToCurve({v.y(), v.z()}, demoBlade().sectionAt(v.x())), 0.006) << i;
    }
    int outward = 0, checked = 0;
    for (std::size_t i = 0; i < mesh->triangles.size(); i += 5) {
        const auto& t = mesh->triangles[i];
        const Vec3 a = corner(*mesh, t, 0), b = corner(*mesh, t, 1), c = corner(*mesh, t, 2);
        const Vec3 centroid = (a + b + c) / 3.0;
        const blade::Curve2 section = demoBlade().sectionAt(centroid.x());
        // A plane cut of a triangle lies within the deflection, widened by the surface's slope.
        ASSERT_LT(blade::distanceToCurve({centroid.y(), centroid.z()}, section),
                  1.1 * options.linearDeflection + 0.006)
            << i;
        const Vec3 n = (b - a).cross(c - a).normalized();
        const Vec3 out = centroid + 0.05 * n, in = centroid - 0.05 * n;
        ++checked;
        outward +=
            !insidePolygon({out.y(), out.z()}, section) && insidePolygon({in.y(), in.z()}, section);
    }
    // Only triangles at the sharp trailing edge, thinner than 0.1 mm, may fail the probe.
    EXPECT_GT(outward, checked * 99 / 100) << outward << " of " << checked;
}

TEST(Tessellation, FinerDeflectionGivesMoreTriangles) {
    const auto coarse = tessellate(demoSurface(), {.linearDeflection = 0.05});
    const auto fine = tessellate(demoSurface(), {.linearDeflection = 0.005});
    ASSERT_TRUE(coarse.has_value() && fine.has_value());
    EXPECT_GT(fine->triangles.size(), coarse->triangles.size());
}

TEST(Tessellation, RefusesBadArguments) {
    EXPECT_EQ(tessellate(CadShape()).error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(tessellate(demoSurface(), {.linearDeflection = -1.0}).error().code,
              ErrorCode::InvalidArgument);
}

} // namespace
} // namespace bladeaxis::cad

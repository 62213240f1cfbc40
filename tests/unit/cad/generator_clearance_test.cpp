// The synthetic generator's original programs against the generator's own blade surface, as CAD
// through OpenCASCADE: the ball centres are offset along the true 3-D surface normal, so no
// member of the seeded family gouges its blade (twist, lean, bow and taper included).

#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/cad/blade_surface.h"
#include "core/cad/clearance.h"
#include "core/cad/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace bladeaxis::cad {
namespace {

constexpr std::uint64_t kSeed = 2022;
constexpr int kMembers = 5; // three cambered NACA, one symmetric, one turbine (presets.h)

ClearanceReport checkMember(const blade::FamilyMember& member) {
    const Result<blade::Blade> blade = blade::Blade::create(member.blade);
    EXPECT_TRUE(blade.has_value()) << member.name;
    const Result<blade::GeneratedPath> path = blade::generateHelicalPath(*blade, member.path);
    EXPECT_TRUE(path.has_value()) << member.name << ": " << path.error().toString();
    const Result<CadShape> surface = makeBladeSurface(*blade);
    EXPECT_TRUE(surface.has_value()) << member.name << ": " << surface.error().toString();
    const Result<TriangleMesh> mesh = tessellate(*surface, {.linearDeflection = 0.01});
    EXPECT_TRUE(mesh.has_value()) << member.name;
    const Result<SurfaceSamples> samples = SurfaceSamples::create(*mesh, 0.25);
    EXPECT_TRUE(samples.has_value()) << member.name;
    ToolGeometry tool;
    tool.ballRadius = member.path.toolRadius;
    const Result<ClearanceReport> report = checkClearance(*samples, path->path, tool);
    EXPECT_TRUE(report.has_value()) << member.name << ": " << report.error().toString();
    return *report;
}

TEST(GeneratorClearance, OriginalProgramsOfTheSyntheticFamilyDoNotGougeTheirBlade) {
    const Result<std::vector<blade::FamilyMember>> family = blade::syntheticFamily(kSeed, kMembers);
    ASSERT_TRUE(family.has_value()) << family.error().toString();
    const double tolerance = ClearanceOptions{}.gougeTolerance;
    for (const blade::FamilyMember& member : *family) {
        const ClearanceReport report = checkMember(member);
        ASSERT_FALSE(report.records.empty()) << member.name;
        const auto lowest = std::ranges::min_element(
            report.records, {}, [](const RecordClearance& c) { return c.ball; });
        EXPECT_GE(lowest->ball, -tolerance)
            << member.name << ": record " << (lowest - report.records.begin());
        EXPECT_TRUE(report.issues.empty())
            << member.name << ": " << report.issues.size() << " issues, first "
            << describe(report.issues.front(), "generated");
    }
}

} // namespace
} // namespace bladeaxis::cad

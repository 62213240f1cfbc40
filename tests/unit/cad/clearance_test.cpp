#include "core/blade/closed_curve.h"
#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/cad/blade_surface.h"
#include "core/cad/clearance.h"
#include "core/cad/tessellation.h"
#include "core/scheduling/schedule.h"
#include "tests/unit/cad/cad_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace bladeaxis::cad {
namespace {

using testing::demoBlade;
using testing::demoSurface;

const SurfaceSamples& demoSamples() {
    static const SurfaceSamples samples =
        *SurfaceSamples::create(*tessellate(demoSurface(), {.linearDeflection = 0.01}), 0.25);
    return samples;
}

// The demo path with made-up source lines (the generator leaves them 0).
const blade::GeneratedPath& demoPath() {
    static const blade::GeneratedPath path = [] {
        blade::GeneratedPath generated =
            *blade::generateHelicalPath(demoBlade(), blade::demoPathSpec());
        generated.path.sourceFile = "demo_blade.nc";
        for (std::size_t i = 0; i < generated.path.records.size(); ++i) {
            generated.path.records[i].line = static_cast<int>(i) + 7;
        }
        return generated;
    }();
    return path;
}

ToolGeometry demoTool() {
    ToolGeometry tool;
    tool.ballRadius = blade::demoPathSpec().toolRadius;
    return tool;
}

const ClearanceReport& demoReport() {
    static const ClearanceReport report =
        *checkClearance(demoSamples(), demoPath().path, demoTool());
    return report;
}

std::size_t countIssues(const ClearanceReport& report, ClearanceKind kind) {
    return static_cast<std::size_t>(std::ranges::count_if(
        report.issues, [kind](const ClearanceIssue& issue) { return issue.kind == kind; }));
}

// Distance from p to a frustum's solid by brute force: a dense walk along its profile and an
// inside test from the definition.
double bruteForceDistance(const AxialFrustum& f, double t, double rho) {
    const double r1 = f.r0 + f.slope * (f.t1 - f.t0);
    const std::array<Vec2, 4> profile{Vec2(f.t0, 0.0), Vec2(f.t0, f.r0), Vec2(f.t1, r1),
                                      Vec2(f.t1, 0.0)};
    double best = 1e300;
    for (std::size_t k = 0; k < 3; ++k) {
        for (int s = 0; s <= 20000; ++s) {
            const Vec2 q = profile[k] + (profile[k + 1] - profile[k]) * (s / 20000.0);
            best = std::min(best, (q - Vec2(t, rho)).norm());
        }
    }
    const bool inside = t >= f.t0 && t <= f.t1 && rho <= f.r0 + f.slope * (t - f.t0);
    return inside ? -best : best;
}

TEST(ToolGeometry, FrustumSignedDistanceMatchesADenseProfileWalk) {
    ToolGeometry tool;
    tool.taperHalfAngle = 0.1;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> t(-20.0, 80.0), rho(0.0, 30.0);
    for (const AxialFrustum& solid : {shankSolid(tool), holderSolid(tool)}) {
        for (int i = 0; i < 300; ++i) {
            const double a = t(rng), b = rho(rng);
            ASSERT_NEAR(signedDistance(solid, a, b), bruteForceDistance(solid, a, b), 0.01)
                << a << " " << b;
        }
    }
}

TEST(ToolGeometry, TaperedShankTouchesTheBallTangentially) {
    ToolGeometry tool;
    tool.taperHalfAngle = 0.2;
    const AxialFrustum shank = shankSolid(tool);
    // The tangency circle lies on the ball; the cone widens with the taper.
    EXPECT_NEAR(std::hypot(shank.t0, shank.r0), tool.ballRadius, 1e-12);
    EXPECT_NEAR(shank.slope, std::tan(0.2), 1e-12);
    // On the axis the cone's side is nearer than the end faces.
    EXPECT_NEAR(signedDistance(shank, 10.0, 0.0),
                -(shank.r0 + shank.slope * (10.0 - shank.t0)) * std::cos(0.2), 1e-12);
}

TEST(ToolGeometry, ValidationRefusesImpossibleTools) {
    EXPECT_TRUE(validate(ToolGeometry{}).has_value());
    EXPECT_FALSE(validate(ToolGeometry{.ballRadius = 0.0}).has_value());
    EXPECT_FALSE(validate(ToolGeometry{.taperHalfAngle = 1.2}).has_value());
    EXPECT_FALSE(validate(ToolGeometry{.ballRadius = 8.0, .stickOut = 15.0}).has_value());
}

TEST(SurfaceSamples, MinimumEqualsABruteForceScan) {
    const SurfaceSamples& samples = demoSamples();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-5.0, 25.0), yz(-50.0, 50.0);
    const AxialFrustum shank = shankSolid(ToolGeometry{});
    for (int i = 0; i < 20; ++i) {
        const Vec3 q(x(rng), yz(rng), yz(rng));
        const Vec3 v = Vec3(yz(rng), yz(rng), yz(rng)).normalized();
        auto toShank = [&](const Vec3& p) {
            const double t = (p - q).dot(v);
            return signedDistance(shank, t, (p - q - t * v).norm());
        };
        double ball = 1e300, frustum = 1e300;
        for (const Vec3& p : samples.points()) {
            ball = std::min(ball, (p - q).norm());
            frustum = std::min(frustum, toShank(p));
        }
        EXPECT_DOUBLE_EQ(samples.minimum([&](const Vec3& p) { return (p - q).norm(); }, 1e300),
                         ball);
        EXPECT_DOUBLE_EQ(samples.minimum(toShank, 1e300), frustum);
        EXPECT_EQ(samples.minimum([&](const Vec3& p) { return (p - q).norm(); }, ball / 2),
                  ball / 2); // nothing nearer than the limit
    }
}

TEST(SurfaceSamples, CoverEveryPointOfTheMeshWithinTheCoverageRadius) {
    const TriangleMesh mesh = *tessellate(demoSurface(), {.linearDeflection = 0.05});
    const SurfaceSamples samples = *SurfaceSamples::create(mesh, 0.5);
    EXPECT_LE(samples.coverageRadius(), 2 * 0.5);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> pick(0, mesh.triangles.size() - 1);
    for (int i = 0; i < 200; ++i) {
        const auto& t = mesh.triangles[pick(rng)];
        double a = unit(rng), b = unit(rng);
        if (a + b > 1.0) {
            a = 1.0 - a;
            b = 1.0 - b;
        }
        const Vec3 p = mesh.vertices[t[0]] + a * (mesh.vertices[t[1]] - mesh.vertices[t[0]]) +
                       b * (mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        EXPECT_LE(samples.minimum([&](const Vec3& s) { return (s - p).norm(); }, 1e300),
                  samples.coverageRadius());
    }
}

// The ball clearance is an independent measurement: the distance from Q to the analytic blade
// (a fine scan over x of the generator's sections) agrees with the sampled CAD surface. The
// generator offsets Q along the true 3-D surface normal, so on this twisted blade the ball
// touches the surface without dipping into it: no gouge anywhere.
TEST(Clearance, BallClearanceAgreesWithTheAnalyticBladeAndNeverGouges) {
    const ClearanceReport& report = demoReport();
    ASSERT_EQ(report.records.size(), demoPath().path.records.size());
    for (std::size_t k = 50; k < report.records.size(); k += 211) {
        const Vec3 q = demoPath().centre[k];
        double nearest = 1e300;
        for (double x = std::max(0.0, q.x() - 8.0); x <= std::min(20.0, q.x() + 8.0); x += 0.005) {
            const double inPlane = blade::distanceToCurve({q.y(), q.z()}, demoBlade().sectionAt(x));
            nearest = std::min(nearest, std::hypot(x - q.x(), inPlane));
        }
        EXPECT_NEAR(nearest, demoTool().ballRadius, 2e-3) << k;
        // Sampling overestimates a distance by up to about e^2 / (2 R) for the sample offset e
        // <= coverage radius (0.5 mm here), plus the 0.01 mm mesh deflection.
        EXPECT_NEAR(report.records[k].ball, nearest - demoTool().ballRadius, 0.03) << k;
    }
    const double tolerance = ClearanceOptions{}.gougeTolerance;
    EXPECT_EQ(countIssues(report, ClearanceKind::Gouge), 0u);
    for (std::size_t k = 0; k < report.records.size(); ++k) {
        ASSERT_GE(report.records[k].ball, -tolerance) << k;
    }
}

TEST(Clearance, OriginalDemoPathHasNoShankOrHolderCollision) {
    const ClearanceReport& report = demoReport();
    EXPECT_EQ(countIssues(report, ClearanceKind::ShankCollision), 0u);
    EXPECT_EQ(countIssues(report, ClearanceKind::HolderCollision), 0u);
    const double limit = ClearanceOptions{}.searchLimit;
    for (const RecordClearance& c : report.records) {
        ASSERT_GT(c.shank, 1.0);
        ASSERT_LE(c.shank, limit);
        ASSERT_EQ(c.holder, limit); // nothing within the search limit of the holder
    }
}

// A tool axis turned 100 deg from the surface normal in the section plane leans past the
// tangent into the blade: the shank cuts through it.
TEST(Clearance, FindsAnInjectedGougingOrientationWithItsSourceLine) {
    const std::size_t k = 977;
    toolpath::Toolpath path = demoPath().path;
    const Vec3 n = demoPath().normal[k];
    const Vec3 q = demoPath().centre[k];
    const Vec3 leaning = (rotationX(std::numbers::pi * 100.0 / 180.0) * n).normalized();
    path.records[k].axis = leaning;
    path.records[k].tip = q - demoTool().ballRadius * leaning;
    const Result<ClearanceReport> report = checkClearance(demoSamples(), path, demoTool());
    ASSERT_TRUE(report.has_value()) << report.error().toString();
    std::vector<ClearanceIssue> collisions;
    for (const ClearanceIssue& issue : report->issues) {
        if (issue.kind == ClearanceKind::ShankCollision) {
            collisions.push_back(issue);
        }
    }
    ASSERT_EQ(collisions.size(), 1u);
    EXPECT_EQ(collisions[0].record, k);
    EXPECT_EQ(collisions[0].line, path.records[k].line);
    EXPECT_GT(collisions[0].depth, 1.0);
    EXPECT_EQ(
        describe(collisions[0], path.sourceFile).rfind("demo_blade.nc:984: shank collision", 0),
        0u);
    // The ball centre did not move, so its clearance did not change.
    EXPECT_DOUBLE_EQ(report->records[k].ball, demoReport().records[k].ball);
    const auto layer = std::ranges::find_if(
        report->layers, [&](const LayerClearance& l) { return l.first <= k && k <= l.last; });
    ASSERT_NE(layer, report->layers.end());
    EXPECT_EQ(layer->minimum.shank, report->records[k].shank);
}

TEST(Clearance, FindsABallPushedIntoTheBlade) {
    const std::size_t k = 1500;
    toolpath::Toolpath path = demoPath().path;
    path.records[k].tip -= 1.0 * demoPath().normal[k];
    const Result<ClearanceReport> report = checkClearance(demoSamples(), path, demoTool());
    ASSERT_TRUE(report.has_value()) << report.error().toString();
    const auto gouge = std::ranges::find_if(report->issues, [&](const ClearanceIssue& issue) {
        return issue.record == k && issue.kind == ClearanceKind::Gouge;
    });
    ASSERT_NE(gouge, report->issues.end());
    EXPECT_NEAR(gouge->depth, 1.0 - demoReport().records[k].ball, 0.05);
}

toolpath::Toolpath rescheduledPath(const toolpath::Toolpath& original, double radius) {
    scheduling::ScheduleInput input;
    input.toolRadius = radius;
    for (const toolpath::ClRecord& record : original.records) {
        input.centres.push_back(record.tip + radius * record.axis.normalized());
        input.axes.push_back(record.axis);
    }
    const auto scheduled = scheduling::schedule(input, scheduling::bestPreset());
    EXPECT_TRUE(scheduled.has_value()) << scheduled.error().toString();
    toolpath::Toolpath rescheduled = original;
    for (std::size_t i = 0; scheduled && i < rescheduled.records.size(); ++i) {
        rescheduled.records[i].tip = tipOfBall(input.centres[i], scheduled->newAxes[i], radius);
        rescheduled.records[i].axis = scheduled->newAxes[i];
    }
    return rescheduled;
}

double largestTurn(const toolpath::Toolpath& a, const toolpath::Toolpath& b) {
    double turned = 0.0;
    for (std::size_t i = 0; i < a.records.size(); ++i) {
        const double c = a.records[i].axis.normalized().dot(b.records[i].axis.normalized());
        turned = std::max(turned, std::acos(std::clamp(c, -1.0, 1.0)));
    }
    return turned;
}

// On a blade without twist, lean or bow every section plane is a true normal plane, so the
// engine's 2-D channel (spec §2) is exact in 3-D: the re-scheduled program, which keeps the
// ball centres and turns the axis inside the channel, must be free of gouges and collisions
// (within the mesh deflection and sampling error).
TEST(Clearance, RescheduledPrismaticBladeIsFreeOfGougesAndCollisions) {
    blade::BladeSpec spec = blade::demoBladeSpec();
    spec.staggerStart = spec.staggerEnd = 0.436;
    const blade::Blade prism = *blade::Blade::create(spec);
    const SurfaceSamples samples = *SurfaceSamples::create(
        *tessellate(*makeBladeSurface(prism), {.linearDeflection = 0.01}), 0.25);
    const toolpath::Toolpath original =
        blade::generateHelicalPath(prism, blade::demoPathSpec())->path;
    const toolpath::Toolpath rescheduled = rescheduledPath(original, demoTool().ballRadius);
    EXPECT_GT(largestTurn(original, rescheduled), 0.2) << "the schedule turned the axis";
    ClearanceOptions tolerant;
    tolerant.gougeTolerance = 0.02;
    tolerant.minimumClearance = -0.02;
    for (const toolpath::Toolpath* path : {&original, &rescheduled}) {
        const Result<ClearanceReport> report = checkClearance(samples, *path, demoTool(), tolerant);
        ASSERT_TRUE(report.has_value()) << report.error().toString();
        EXPECT_TRUE(report->issues.empty())
            << report->issues.size()
            << " issues, first: " << describe(report->issues.front(), path->sourceFile);
    }
}

// The generator's ball centres touch the twisted demo blade without gouging it (see
// BallClearanceAgreesWithTheAnalyticBladeAndNeverGouges), and the re-scheduled axis turns inside
// the engine's channel: in 3-D the output then neither gouges nor collides, so the demo's own
// export is not refused.
TEST(Clearance, RescheduledDemoIsFreeOfGougesAndCollisions) {
    const toolpath::Toolpath rescheduled = rescheduledPath(demoPath().path, demoTool().ballRadius);
    EXPECT_GT(largestTurn(demoPath().path, rescheduled), 0.2) << "the schedule turned the axis";
    const Result<ClearanceReport> report = checkClearance(demoSamples(), rescheduled, demoTool());
    ASSERT_TRUE(report.has_value()) << report.error().toString();
    double minShank = 1e300;
    for (std::size_t i = 0; i < report->records.size(); ++i) {
        ASSERT_NEAR(report->records[i].ball, demoReport().records[i].ball, 1e-6) << i; // kept
        minShank = std::min(minShank, report->records[i].shank);
    }
    EXPECT_TRUE(report->issues.empty())
        << report->issues.size()
        << " issues, first: " << describe(report->issues.front(), rescheduled.sourceFile);
    RecordProperty("min_shank_clearance_um", static_cast<int>(std::lround(minShank * 1000.0)));
}

TEST(Clearance, SearchLimitOnlyCapsDistancesBeyondIt) {
    ClearanceOptions exact;
    exact.searchLimit = std::numeric_limits<double>::infinity();
    const Result<ClearanceReport> full =
        checkClearance(demoSamples(), demoPath().path, demoTool(), exact);
    ASSERT_TRUE(full.has_value()) << full.error().toString();
    const double limit = ClearanceOptions{}.searchLimit;
    for (std::size_t i = 0; i < full->records.size(); ++i) {
        const RecordClearance& a = full->records[i];
        const RecordClearance& b = demoReport().records[i];
        ASSERT_EQ(b.ball, std::min(a.ball, limit)) << i;
        ASSERT_EQ(b.shank, std::min(a.shank, limit)) << i;
        ASSERT_EQ(b.holder, std::min(a.holder, limit)) << i;
    }
}

TEST(Clearance, LayersPartitionTheRecordsByRevolution) {
    const ClearanceReport& report = demoReport();
    ASSERT_GE(report.layers.size(), 8u);
    std::size_t next = 0;
    for (const LayerClearance& layer : report.layers) {
        ASSERT_EQ(layer.first, next);
        next = layer.last + 1;
        double minShank = 1e300;
        for (std::size_t i = layer.first; i <= layer.last; ++i) {
            minShank = std::min(minShank, report.records[i].shank);
        }
        EXPECT_EQ(layer.minimum.shank, minShank);
    }
    EXPECT_EQ(next, report.records.size());
    const std::size_t perLayer = report.records.size() / report.layers.size();
    EXPECT_GT(report.layers[3].last - report.layers[3].first + 1, perLayer / 2);
}

TEST(Clearance, RefusesBadInputs) {
    toolpath::Toolpath path = demoPath().path;
    EXPECT_FALSE(checkClearance(demoSamples(), path, ToolGeometry{.ballRadius = -1.0}));
    ClearanceOptions gaps;
    gaps.layers = {{0, 10}, {12, path.records.size() - 1}};
    EXPECT_EQ(checkClearance(demoSamples(), path, demoTool(), gaps).error().code,
              ErrorCode::InvalidArgument);
    path.records[3].axis = Vec3::Zero();
    const auto zero = checkClearance(demoSamples(), path, demoTool());
    ASSERT_FALSE(zero.has_value());
    EXPECT_EQ(zero.error().code, ErrorCode::Geometry);
    EXPECT_EQ(zero.error().where.line, path.records[3].line);
}

} // namespace
} // namespace bladeaxis::cad

// What the 3-D view draws: the blade surface from the CAD or reconstructed from the contact
// points, the section of every layer, the drawn points and their decimation.

#include "core/cad/surface_samples.h"
#include "core/job/display_scene.h"
#include "core/job/job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bladeaxis::job {
namespace {

const JobResult& demoResult() {
    static const JobResult result = [] {
        JobSpec spec;
        spec.demo = true;
        NullProgressSink progress;
        CancelToken cancel;
        auto job = runJob(spec, progress, cancel);
        EXPECT_TRUE(job.has_value()) << job.error().toString();
        return std::move(*job);
    }();
    return result;
}

DisplaySceneInput demoInputWithoutCad() {
    const JobResult& result = demoResult();
    DisplaySceneInput input;
    input.pass =
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
    input.toolRadius = *result.toolRadius;
    input.schedule = &result.rescheduled->schedule;
    input.originalProfile = &result.original;
    input.rescheduledProfile = &result.rescheduled->profile;
    return input;
}

const cad::SurfaceSamples& demoCadSamples() {
    static const cad::SurfaceSamples samples = [] {
        const DisplayScene scene = buildDisplayScene(demoResult());
        auto created = cad::SurfaceSamples::create(scene.surface, 0.1);
        EXPECT_TRUE(created.has_value());
        return std::move(*created);
    }();
    return samples;
}

double distanceToCad(const Vec3& point) {
    return demoCadSamples().minimum([&](const Vec3& q) { return (q - point).norm(); }, 1e9);
}

// A helix of ball centres around the x axis: radius 20 mm, pitch 1 mm, the tool axis pointing
// away from the axis (so the blade is the cylinder of radius 20 - R).
std::vector<toolpath::ClRecord> helix(double revolutions, int perRevolution, double sense,
                                      double radius) {
    std::vector<toolpath::ClRecord> records;
    const int count = static_cast<int>(revolutions * perRevolution) + 1;
    for (int i = 0; i < count; ++i) {
        const double angle = sense * 2.0 * std::numbers::pi * i / perRevolution;
        const Vec3 outward(0.0, std::cos(angle), std::sin(angle));
        const Vec3 centre = Vec3(static_cast<double>(i) / perRevolution, 0.0, 0.0) + 20.0 * outward;
        toolpath::ClRecord record;
        record.axis = outward;
        record.tip = centre - radius * outward;
        records.push_back(record);
    }
    return records;
}

TEST(DisplayScene, DemoBladeComesFromItsCadWithTheClearancesTheJobMeasured) {
    const DisplayScene scene = buildDisplayScene(demoResult());
    ASSERT_EQ(scene.surfaceSource, SurfaceSource::Cad);
    ASSERT_FALSE(scene.surface.empty());
    EXPECT_EQ(scene.surfaceNormals.size(), scene.surface.vertices.size());
    // The job's clearance check measured each ball against the same blade: the drawn surface
    // must give the same distances (the demo program itself gouges a little in places).
    const auto& clearances = demoResult().cadCheck->original.records;
    const double radius = *demoResult().toolRadius;
    const double tolerance = 0.05 + demoCadSamples().coverageRadius();
    for (std::size_t i = 0; i < scene.centres.size(); i += scene.centres.size() / 97 + 1) {
        const double ballClearance = clearances[scene.record[i]].ball;
        EXPECT_NEAR(distanceToCad(scene.centres[i]) - radius, ballClearance, tolerance)
            << "point " << i;
    }
}

TEST(DisplayScene, WithoutCadTheSurfaceIsReconstructedOnTheBlade) {
    const DisplayScene scene = buildDisplayScene(demoInputWithoutCad());
    ASSERT_EQ(scene.surfaceSource, SurfaceSource::Reconstructed);
    ASSERT_GT(scene.surface.triangles.size(), 100u);
    const auto& vertices = scene.surface.vertices;
    // The reconstruction steps R along the 3-D normal of the centres' surface, the one the demo
    // offset its ball centres along (the twist tilts it out of the section plane by up to ~15
    // deg, where a step in that plane would miss the blade by up to R (1 - cos 15 deg) = 0.27
    // mm), also round the blade's edges: every vertex within 0.05 mm of the blade, give or take
    // the spacing of the samples the distance is measured to.
    const double tolerance = 0.05 + demoCadSamples().coverageRadius();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        EXPECT_LT(distanceToCad(vertices[i]), tolerance) << "vertex " << i;
    }
}

TEST(DisplayScene, EveryScheduledLayerHasItsCadSectionInItsPlane) {
    const DisplayScene scene = buildDisplayScene(demoResult());
    ASSERT_EQ(scene.layers.size(), demoResult().rescheduled->schedule.layers.size());
    const double radius = *demoResult().toolRadius;
    for (const DisplayLayer& layer : scene.layers) {
        ASSERT_FALSE(layer.section.empty());
        for (const cad::Polyline3& piece : layer.section) {
            for (const Vec3& point : piece.points) {
                EXPECT_NEAR(point.x(), layer.sectionX, 1e-6);
            }
        }
        // The section surrounds the ball centres of its layer at about one radius.
        const Vec3& centre = scene.centres[(layer.firstPoint + layer.lastPoint) / 2];
        double nearest = 1e9;
        for (const cad::Polyline3& piece : layer.section) {
            for (const Vec3& point : piece.points) {
                const Vec2 inPlane(point.y() - centre.y(), point.z() - centre.z());
                nearest = std::min(nearest, inPlane.norm());
            }
        }
        EXPECT_NEAR(nearest, radius, 0.5);
    }
}

TEST(DisplayScene, PointsCarryTheirLayerBothOrientationsAndTheirASpeeds) {
    const DisplayScene scene = buildDisplayScene(demoResult());
    const std::size_t n = scene.record.size();
    ASSERT_GT(n, 0u);
    EXPECT_EQ(scene.passRecords, demoResult().pass.count);
    EXPECT_EQ(scene.tips.size(), n);
    EXPECT_EQ(scene.originalAxes.size(), n);
    ASSERT_TRUE(scene.hasRescheduled());
    EXPECT_EQ(scene.rescheduledAxes.size(), n);
    ASSERT_EQ(scene.aSpeedOriginal.size(), n);
    ASSERT_EQ(scene.aSpeedRescheduled.size(), n);
    for (std::size_t k = 0; k < scene.layers.size(); ++k) {
        const DisplayLayer& layer = scene.layers[k];
        for (std::size_t i = layer.firstPoint; i <= layer.lastPoint; ++i) {
            ASSERT_EQ(scene.layer[i], k);
            ASSERT_GE(scene.record[i], layer.firstRecord);
            ASSERT_LE(scene.record[i], layer.lastRecord);
        }
    }
    // The demo's original reverses A, the re-scheduled one turns it smoothly: the speeds differ.
    EXPECT_NE(scene.aSpeedOriginal, scene.aSpeedRescheduled);
    const double peakOriginal =
        *std::max_element(scene.aSpeedOriginal.begin(), scene.aSpeedOriginal.end());
    EXPECT_NEAR(peakOriginal, demoResult().original.axis(kinematics::AxisId::A).peakVelocity,
                0.05 * peakOriginal);
}

TEST(DisplayScene, DecimationKeepsTheLimitsAndTheLayerStarts) {
    DisplaySceneInput input = demoInputWithoutCad();
    input.limits.maxPathPoints = 500;
    input.limits.maxGlyphs = 40;
    input.limits.maxSurfaceVertices = 300;
    const DisplayScene scene = buildDisplayScene(input);
    ASSERT_GT(input.pass.size(), 1500u) << "the demo pass is too short to test decimation";
    EXPECT_LE(scene.record.size(), 500u + scene.layers.size() + 1);
    EXPECT_LE(scene.glyphPoints.size(), 40u);
    EXPECT_LE(scene.surface.vertices.size(), 300u);
    EXPECT_FALSE(scene.surface.empty());
    EXPECT_EQ(scene.record.front(), 0u);
    EXPECT_EQ(scene.record.back(), input.pass.size() - 1);
    for (const DisplayLayer& layer : scene.layers) {
        EXPECT_EQ(scene.record[layer.firstPoint], layer.firstRecord);
    }
    EXPECT_EQ(scene.passRecords, input.pass.size());
}

TEST(DisplayScene, UnscheduledHelixIsSplitIntoRevolutions) {
    const auto records = helix(5.5, 120, 1.0, 3.0);
    DisplaySceneInput input;
    input.pass = records;
    input.toolRadius = 3.0;
    const DisplayScene scene = buildDisplayScene(input);
    EXPECT_EQ(scene.layers.size(), 6u);
    EXPECT_FALSE(scene.hasRescheduled());
    EXPECT_TRUE(scene.aSpeedOriginal.empty());
    for (const DisplayLayer& layer : scene.layers) {
        ASSERT_EQ(layer.section.size(), 1u);
        EXPECT_GT(layer.section.front().points.size(), 50u);
    }
}

class ReconstructedHelix : public testing::TestWithParam<double> {};

TEST_P(ReconstructedHelix, ContactPointsLieOnTheCylinderWithOutwardNormals) {
    const double radius = 3.0;
    const auto records = helix(4.0, 90, GetParam(), radius);
    DisplaySceneInput input;
    input.pass = records;
    input.toolRadius = radius;
    const DisplayScene scene = buildDisplayScene(input);
    ASSERT_EQ(scene.surfaceSource, SurfaceSource::Reconstructed);
    // One revolution less than the path is covered by the ribbon, two triangles per point.
    EXPECT_GT(scene.surface.triangles.size(), 2u * 90u * 3u - 10u);
    const auto& mesh = scene.surface;
    for (const Vec3& v : mesh.vertices) {
        EXPECT_NEAR(std::hypot(v.y(), v.z()), 20.0 - radius, 0.01);
    }
    for (const auto& t : mesh.triangles) {
        const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
        const Vec3 normal = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        EXPECT_GT(normal.dot(Vec3(0.0, centroid.y(), centroid.z())), 0.0);
    }
}

INSTANTIATE_TEST_SUITE_P(BothTurningSenses, ReconstructedHelix, testing::Values(1.0, -1.0));

} // namespace
} // namespace bladeaxis::job

// Spec §10.2 pipeline invariants and §10.3 degenerate cases on synthetic helical paths.
#include "core/base/parallel.h"
#include "core/scheduling/schedule.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

bool hasFlag(const LayerResult& layer, LayerStatus status) {
    return std::find(layer.flags.begin(), layer.flags.end(), status) != layer.flags.end();
}

ScheduleInput appendixBHelix(double revolutions = 3.0) {
    testing::HelixOptions options;
    options.revolutions = revolutions;
    return testing::helicalPath(testing::appendixBCurve(), options);
}

TEST(Schedule, AppendixBHelixIsMonotoneInsideTheChannelWithFlatEnds) {
    const ScheduleInput input = appendixBHelix();
    for (const ScheduleParameters& parameters : {bestPreset(), faithfulPreset()}) {
        auto result = schedule(input, parameters);
        ASSERT_TRUE(result.has_value()) << result.error().toString();
        ASSERT_EQ(result->layers.size(), 4u); // 3 revolutions: 3 base points, 2 partial ends
        EXPECT_EQ(result->check.reversals, 0u);
        EXPECT_GT(result->originalReversals, 0u);
        for (std::size_t k = 0; k < result->layers.size(); ++k) {
            const LayerResult& layer = result->layers[k];
            EXPECT_FALSE(hasFlag(layer, LayerStatus::MonotoneInfeasible)) << k;
            EXPECT_GE(layer.minClearance, -1e-12) << k;
            for (std::size_t i = 1; i < layer.theta.size(); ++i) {
                ASSERT_GE(layer.theta[i] - layer.theta[i - 1], -1e-12) << k << " " << i;
                ASSERT_GE(layer.dTheta[i], -1e-12);
            }
            const bool intermediate = k > 0 && k + 1 < result->layers.size();
            if (k > 0) { // flat start (fixed junction)
                EXPECT_NEAR(layer.dTheta.front(), 0.0, 1e-9);
                EXPECT_NEAR(layer.ddTheta.front(), 0.0, 1e-9);
            }
            if (k + 1 < result->layers.size()) {
                EXPECT_NEAR(layer.dTheta.back(), 0.0, 1e-9);
                EXPECT_NEAR(layer.ddTheta.back(), 0.0, 1e-9);
            }
            if (intermediate) {
                EXPECT_NEAR(layer.theta.back(), 2.0 * kPi, 0.2); // about one turn, no twist
            }
        }
        EXPECT_TRUE(result->check.passes());
    }
}

TEST(Schedule, ReconstructionKeepsEveryBallCentre) {
    const ScheduleInput input = appendixBHelix(2.5);
    auto result = schedule(input, bestPreset());
    ASSERT_TRUE(result.has_value());
    ASSERT_EQ(result->newAxes.size(), input.centres.size());
    for (std::size_t i = 0; i < input.centres.size(); ++i) {
        const Vec3& v = result->newAxes[i];
        const Vec3 tip = tipOfBall(input.centres[i], v, input.toolRadius);
        EXPECT_NEAR((tip + input.toolRadius * v - input.centres[i]).norm(), 0.0, 1e-9);
        EXPECT_NEAR(v.norm(), 1.0, 1e-12);
        EXPECT_NEAR(v.x(), std::sin(result->tiltB0), 1e-12);
    }
    EXPECT_NEAR(result->tiltB0, 5.0 * kPi / 180.0, 1e-12);
    // Junction continuity: consecutive samples differ by a small step only.
    for (std::size_t i = 1; i < input.centres.size(); ++i) {
        ASSERT_LT((result->newAxes[i] - result->newAxes[i - 1]).norm(), 0.1) << i;
    }
}

TEST(Schedule, ParallelRunEqualsSerialRun) {
    const ScheduleInput input = appendixBHelix(4.0);
    auto a = schedule(input, bestPreset());
    auto b = [&] {
        const ThreadCountScope four(4);
        return schedule(input, bestPreset());
    }();
    ASSERT_TRUE(a.has_value() && b.has_value());
    ASSERT_EQ(a->layers.size(), b->layers.size());
    EXPECT_EQ(absoluteAngles(*a, Orientation::Rescheduled),
              absoluteAngles(*b, Orientation::Rescheduled)); // bit-identical
    for (std::size_t k = 0; k < a->layers.size(); ++k) {
        EXPECT_EQ(a->layers[k].ddTheta, b->layers[k].ddTheta);
        EXPECT_EQ(a->layers[k].polyline, b->layers[k].polyline);
    }
}

// Every per-point stage splits a path this long into ranges on several threads (parallel.h);
// the result must not depend on the split, down to the last bit.
TEST(Schedule, ParallelStagesGiveTheSerialResultOnALongPath) {
    const ScheduleInput input = appendixBHelix(140.0);
    ASSERT_GT(input.centres.size(), 3 * kMinParallelRange);
    auto a = schedule(input, bestPreset());
    const ThreadCountScope three(3); // ranges that do not fall on layer boundaries
    auto b = schedule(input, bestPreset());
    ASSERT_TRUE(a.has_value() && b.has_value());
    for (Orientation which : {Orientation::Rescheduled, Orientation::Original}) {
        const std::vector<double> one = [&] {
            const ThreadCountScope serial(1);
            return absoluteAngles(a->layers, input.centres.size(), which);
        }();
        EXPECT_EQ(one, absoluteAngles(b->layers, input.centres.size(), which));
    }
    EXPECT_EQ(a->newAxes, b->newAxes);
    EXPECT_EQ(a->basePoints, b->basePoints);
    EXPECT_EQ(a->warnings, b->warnings);
    EXPECT_EQ(a->check.maxCentreErrorMm, b->check.maxCentreErrorMm);
    EXPECT_EQ(a->check.maxUnitError, b->check.maxUnitError);
    EXPECT_EQ(a->check.maxTiltError, b->check.maxTiltError);
    ASSERT_EQ(a->layers.size(), b->layers.size());
    for (std::size_t k = 0; k < a->layers.size(); ++k) {
        EXPECT_EQ(a->layers[k].theta, b->layers[k].theta) << k;
        EXPECT_EQ(a->layers[k].lo, b->layers[k].lo) << k;
        EXPECT_EQ(a->layers[k].hi, b->layers[k].hi) << k;
        EXPECT_EQ(a->layers[k].thetaOriginal, b->layers[k].thetaOriginal) << k;
    }
}

TEST(Schedule, ParallelRunReportsTheFirstFaultyPointOfTheInput) {
    ScheduleInput input = appendixBHelix(140.0);
    const std::size_t late = input.centres.size() - 10;
    const std::size_t early = input.centres.size() / 2 + 7; // in a later range than the start
    input.axes[late] = Vec3::Zero();
    input.centres[early].y() = std::numeric_limits<double>::quiet_NaN();
    const ThreadCountScope four(4);
    auto result = schedule(input, bestPreset());
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("point " + std::to_string(early)), std::string::npos)
        << result.error().message;
}

TEST(Schedule, ReleasingTheLayerSamplesKeepsTheNewAxesAndEveryPerLayerFigure) {
    const auto kept = schedule(appendixBHelix(), bestPreset());
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    ScheduleResult released = *kept;
    releaseLayerSamples(released);

    EXPECT_FALSE(kept->layerSamplesReleased);
    EXPECT_TRUE(released.layerSamplesReleased);
    EXPECT_EQ(released.newAxes, kept->newAxes);
    ASSERT_EQ(released.layers.size(), kept->layers.size());
    for (std::size_t k = 0; k < released.layers.size(); ++k) {
        const LayerResult& before = kept->layers[k];
        const LayerResult& after = released.layers[k];
        ASSERT_FALSE(before.theta.empty());
        for (const auto* curve : {&after.thetaOriginal, &after.thetaMin, &after.thetaMax, &after.lo,
                                  &after.hi, &after.theta, &after.dTheta, &after.ddTheta}) {
            EXPECT_TRUE(curve->empty()) << k;
            EXPECT_EQ(curve->capacity(), 0u) << k; // freed, not only cleared
        }
        EXPECT_TRUE(after.inputIndex.empty()) << k;
        // What a layer's report reads stays: its samples' arc lengths, its status and figures.
        EXPECT_EQ(after.s, before.s) << k;
        EXPECT_EQ(after.first, before.first);
        EXPECT_EQ(after.last, before.last);
        EXPECT_EQ(after.flags, before.flags);
        EXPECT_EQ(after.keyPoints.size(), before.keyPoints.size());
        EXPECT_EQ(after.corners.size(), before.corners.size());
        EXPECT_EQ(after.minClearance, before.minClearance);
        EXPECT_EQ(after.leadFraction, before.leadFraction);
        EXPECT_EQ(after.peakSecondDerivative, before.peakSecondDerivative);
    }
}

TEST(Schedule, ThePlannedLayerBoundsAreTheBoundsOfTheResultsLayers) {
    const ScheduleInput input = appendixBHelix();
    const ScheduleSamples samples = samplesOf(input);
    auto path = makePlanePath(samples, bestPreset());
    ASSERT_TRUE(path.has_value()) << path.error().toString();
    auto plan = planLayers(std::move(*path), samples, bestPreset(), nullptr);
    ASSERT_TRUE(plan.has_value()) << plan.error().toString();
    const std::vector<LayerBounds> planned = plan->bounds;
    const auto result = scheduleLayers(std::move(*plan), samples, bestPreset(), nullptr);
    ASSERT_TRUE(result.has_value()) << result.error().toString();

    const std::vector<LayerBounds> expected = layerBounds(*result);
    ASSERT_GT(expected.size(), 1u);
    ASSERT_EQ(planned.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
        EXPECT_EQ(planned[k].first, expected[k].first) << k;
        EXPECT_EQ(planned[k].last, expected[k].last) << k;
    }
}

} // namespace
} // namespace bladeaxis::scheduling

// Spec §10.3 degenerate cases not covered by schedule_cases_test.cpp, each with its documented
// behaviour, and the optional channel rules: lead band (§2.4), allow_nonmonotone (§2.5), global
// visibility (§2.4) and despiking (§4.6).
#include "core/base/units.h"
#include "core/scheduling/channel.h"
#include "core/scheduling/schedule.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {
namespace {

bool hasFlag(const LayerResult& layer, LayerStatus status) {
    return std::find(layer.flags.begin(), layer.flags.end(), status) != layer.flags.end();
}

ScheduleInput helix(double revolutions) {
    testing::HelixOptions options;
    options.revolutions = revolutions;
    return testing::helicalPath(testing::appendixBCurve(), options);
}

void expectMonotoneInsideTheChannel(const ScheduleResult& result) {
    EXPECT_EQ(result.check.reversals, 0u);
    EXPECT_TRUE(result.check.passes());
    for (const LayerResult& layer : result.layers) {
        EXPECT_GE(layer.minClearance, -1e-9);
        for (std::size_t i = 1; i < layer.theta.size(); ++i) {
            ASSERT_GE(layer.theta[i] - layer.theta[i - 1], -1e-12) << i;
        }
    }
}

// A band of lead angles around the surface normal follows the normal backwards in the concave
// run: the monotone hull is empty, the layers are MONOTONE_INFEASIBLE and keep the input axes.
TEST(DegenerateCases, NarrowLeadBandPinchesTheChannelAndKeepsTheOriginal) {
    const ScheduleInput input = helix(3.0);
    ScheduleParameters parameters = bestPreset();
    parameters.leadBand = true;
    parameters.leadBandMinRad = units::degToRad(10.0);
    parameters.leadBandMaxRad = units::degToRad(20.0);
    auto result = schedule(input, parameters);
    ASSERT_TRUE(result.has_value());
    std::size_t infeasible = 0;
    for (std::size_t k = 0; k < result->layers.size(); ++k) {
        const LayerResult& layer = result->layers[k];
        if (!hasFlag(layer, LayerStatus::MonotoneInfeasible)) {
            continue;
        }
        ++infeasible;
        for (std::size_t j = 0; j + 1 < layer.inputIndex.size(); ++j) { // own samples
            const std::size_t i = layer.inputIndex[j];
            EXPECT_LT((result->newAxes[i] - input.axes[i].normalized()).norm(), 1e-15);
        }
    }
    EXPECT_GE(infeasible, 2u);
    EXPECT_FALSE(result->warnings.empty());
}

// A wide band only narrows the channel: every limit moves inward or stays, and the schedule
// keeps its invariants.
TEST(DegenerateCases, WideLeadBandNarrowsTheChannelOnly) {
    const ScheduleInput input = helix(3.0);
    ScheduleParameters banded = bestPreset();
    banded.leadBand = true;
    banded.leadBandMinRad = units::degToRad(-70.0);
    banded.leadBandMaxRad = units::degToRad(70.0);
    auto plain = schedule(input, bestPreset());
    auto narrow = schedule(input, banded);
    ASSERT_TRUE(plain.has_value() && narrow.has_value());
    ASSERT_EQ(plain->layers.size(), narrow->layers.size());
    std::size_t clipped = 0;
    for (std::size_t k = 0; k < plain->layers.size(); ++k) {
        const LayerResult& a = plain->layers[k];
        const LayerResult& b = narrow->layers[k];
        ASSERT_EQ(a.thetaMax.size(), b.thetaMax.size());
        const double shift = b.junctionAngle - a.junctionAngle; // relative to other references
        for (std::size_t i = 0; i < a.thetaMax.size(); ++i) {
            EXPECT_LE(b.thetaMax[i] + shift, a.thetaMax[i] + 1e-12);
            EXPECT_GE(b.thetaMin[i] + shift, a.thetaMin[i] - 1e-12);
            clipped += b.thetaMax[i] + shift < a.thetaMax[i] - 1e-9 ? 1 : 0;
        }
    }
    EXPECT_GT(clipped, 0u);
    expectMonotoneInsideTheChannel(*narrow);
}

// allow_nonmonotone: the pinched layers get the original projected onto the raw channel and
// smoothed instead of the original itself; the ball centres are still kept.
TEST(DegenerateCases, AllowNonmonotoneProjectsThePinchedLayersIntoTheChannel) {
    const ScheduleInput input = helix(3.0);
    ScheduleParameters parameters = bestPreset();
    parameters.leadBand = true;
    parameters.leadBandMinRad = units::degToRad(10.0);
    parameters.leadBandMaxRad = units::degToRad(20.0);
    parameters.allowNonmonotone = true;
    auto result = schedule(input, parameters);
    ASSERT_TRUE(result.has_value());
    std::size_t projected = 0;
    for (const LayerResult& layer : result->layers) {
        EXPECT_FALSE(hasFlag(layer, LayerStatus::MonotoneInfeasible));
        if (hasFlag(layer, LayerStatus::NonMonotone)) {
            ++projected;
            EXPECT_GE(layer.minClearance, -1e-12); // inside the raw (lead band) channel
        }
    }
    EXPECT_GE(projected, 2u);
    EXPECT_TRUE(result->check.passes());
}

ScheduleInput firstSamples(const ScheduleInput& full, std::size_t count) {
    ScheduleInput input;
    input.toolRadius = full.toolRadius;
    input.centres.assign(full.centres.begin(), full.centres.begin() + static_cast<long>(count));
    input.axes.assign(full.axes.begin(), full.axes.begin() + static_cast<long>(count));
    return input;
}

// The path ends a few samples after its last base point (the fewest that still let the concave
// run end there): the last layer is shorter than 4 l_t, is flagged, gets no lead segment (a
// straight segment between its end values), starts at the junction and stays in the channel.
TEST(DegenerateCases, LayerShorterThanFourTangentChordsIsAStraightShortLayer) {
    const ScheduleInput full = helix(3.0);
    auto reference = schedule(full, bestPreset());
    ASSERT_TRUE(reference.has_value());
    const std::size_t base = reference->basePoints.back();
    for (std::size_t extra = 2; extra < 40; ++extra) {
        auto result = schedule(firstSamples(full, base + extra + 1), bestPreset());
        ASSERT_TRUE(result.has_value());
        if (result->basePoints != reference->basePoints) {
            continue;
        }
        const LayerResult& last = result->layers.back();
        EXPECT_TRUE(hasFlag(last, LayerStatus::ShortLayer)) << extra;
        EXPECT_EQ(last.polyline.size(), 2u);
        EXPECT_EQ(last.theta.front(), 0.0);
        expectMonotoneInsideTheChannel(*result);
        return;
    }
    FAIL() << "no truncation keeps the last base point";
}

// Chords of 1 um over 20 mm of path (every original chord there split into 1 um steps): the
// tangent chord l_t, not the point spacing, sets the directions, so the result matches the
// sparse path at the shared points.
TEST(DegenerateCases, MicrometreChordsGiveTheSameSchedule) {
    const ScheduleInput sparse = helix(2.0);
    ScheduleInput dense;
    dense.toolRadius = sparse.toolRadius;
    std::vector<std::size_t> original;
    double densified = 0.0;
    for (std::size_t i = 0; i < sparse.centres.size(); ++i) {
        original.push_back(dense.centres.size());
        dense.centres.push_back(sparse.centres[i]);
        dense.axes.push_back(sparse.axes[i]);
        if (i < 400 || i + 1 >= sparse.centres.size() || densified > 20.0) {
            continue;
        }
        const Vec3 step = sparse.centres[i + 1] - sparse.centres[i];
        const auto parts = static_cast<int>(std::ceil(step.norm() / 1e-3));
        for (int k = 1; k < parts; ++k) {
            dense.centres.push_back(sparse.centres[i] + step * (static_cast<double>(k) / parts));
            dense.axes.push_back(sparse.axes[i]);
        }
        densified += step.norm();
    }
    ASSERT_GT(dense.centres.size(), sparse.centres.size() + 15000);
    auto a = schedule(sparse, bestPreset());
    auto b = schedule(dense, bestPreset());
    ASSERT_TRUE(a.has_value() && b.has_value());
    EXPECT_EQ(a->layers.size(), b->layers.size());
    expectMonotoneInsideTheChannel(*b);
    const std::vector<double> sparseAngles = absoluteAngles(*a, Orientation::Rescheduled);
    const std::vector<double> denseAngles = absoluteAngles(*b, Orientation::Rescheduled);
    double worst = 0.0;
    for (std::size_t i = 0; i < original.size(); ++i) {
        worst = std::max(worst, std::abs(sparseAngles[i] - denseAngles[original[i]]));
    }
    EXPECT_LT(worst, units::degToRad(3.0));
}

// A varying input tilt B is reported and replaced by its median; the output tilt is constant.
TEST(DegenerateCases, NonConstantInputTiltWarnsAndUsesTheMedian) {
    ScheduleInput input = helix(2.0);
    for (std::size_t i = 0; i < input.axes.size(); ++i) {
        const double wobble = 1e-3 * std::sin(0.05 * static_cast<double>(i));
        input.axes[i] = Eigen::AngleAxisd(wobble, Vec3::UnitY()) * input.axes[i];
    }
    auto result = schedule(input, bestPreset());
    ASSERT_TRUE(result.has_value());
    const bool warned =
        std::any_of(result->warnings.begin(), result->warnings.end(), [](const std::string& w) {
            return w.find("tilt B is not constant") != w.npos;
        });
    EXPECT_TRUE(warned);
    EXPECT_NEAR(result->tiltB0, units::degToRad(5.0), 1.1e-3);
    for (const Vec3& v : result->newAxes) {
        ASSERT_NEAR(v.x(), std::sin(result->tiltB0), 1e-12);
    }
    expectMonotoneInsideTheChannel(*result);
}

// §2.4 global visibility only ever narrows the channel, and the schedule keeps its invariants.
TEST(ChannelOptions, GlobalVisibilityOnlyNarrowsTheChannel) {
    const ScheduleInput input = helix(3.0);
    ScheduleParameters global = bestPreset();
    global.visibility = Visibility::Global;
    auto local = schedule(input, bestPreset());
    auto clipped = schedule(input, global);
    ASSERT_TRUE(local.has_value() && clipped.has_value());
    ASSERT_EQ(local->basePoints, clipped->basePoints);
    for (std::size_t k = 0; k < local->layers.size(); ++k) {
        const LayerResult& a = local->layers[k];
        const LayerResult& b = clipped->layers[k];
        const double shift = b.junctionAngle - a.junctionAngle;
        for (std::size_t i = 0; i < a.thetaMax.size(); ++i) {
            ASSERT_LE(b.thetaMax[i] + shift, a.thetaMax[i] + 1e-12) << k << " " << i;
            ASSERT_GE(b.thetaMin[i] + shift, a.thetaMin[i] - 1e-12) << k << " " << i;
        }
    }
    expectMonotoneInsideTheChannel(*clipped);
}

// Points ahead inside the forward limit's half-plane clip it: a pocket whose far wall is seen
// from a point before it.
TEST(ChannelOptions, GlobalVisibilityClipsTheForwardLimitAtAPocketWall) {
    const std::vector<Vec2> points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, -1}, {4, -1}, {4, 2}};
    RawChannel channel{DefaultInitVector<double>(points.size(), -3.0),
                       DefaultInitVector<double>(points.size(), 0.0)}; // forward limit along +x
    clipGlobalVisibility(channel, points, 6);
    EXPECT_NEAR(channel.thetaMax[0], std::atan2(-1.0, 3.0), 1e-12); // sees (3, -1) first
    EXPECT_EQ(channel.thetaMax[5], 0.0);                            // (4, 2) lies above
}

// §4.6 despiking: an isolated downward spike of thetaMax (upward of thetaMin) becomes the local
// median of 7; monotone runs are untouched.
TEST(ChannelOptions, DespikeRemovesIsolatedSpikesOnly) {
    RawChannel channel;
    for (int i = 0; i < 20; ++i) {
        channel.thetaMax.push_back(1.0 + 0.01 * i); // monotone: untouched
        channel.thetaMin.push_back(-1.0 + 0.01 * i);
    }
    const RawChannel monotone = channel;
    EXPECT_EQ(despikeChannel(channel), 0u);
    EXPECT_EQ(channel.thetaMax, monotone.thetaMax);
    channel.thetaMax[9] -= 0.5;
    channel.thetaMin[12] += 0.5;
    EXPECT_EQ(despikeChannel(channel), 2u);
    // The spike takes the median of its window, the 4th of 7 with itself at the bottom (top).
    EXPECT_EQ(channel.thetaMax[9], monotone.thetaMax[8]);
    EXPECT_EQ(channel.thetaMin[12], monotone.thetaMin[13]);
    for (std::size_t i = 0; i < 20; ++i) {
        EXPECT_EQ(channel.thetaMax[i], i == 9 ? monotone.thetaMax[8] : monotone.thetaMax[i]);
        EXPECT_EQ(channel.thetaMin[i], i == 12 ? monotone.thetaMin[13] : monotone.thetaMin[i]);
    }
}

TEST(ChannelOptions, DespikeInThePipelineReportsWhatItChanged) {
    ScheduleInput input = helix(2.0);
    for (Vec3& q : input.centres) { // rounding noise makes small downward spikes
        q = (q * 1000.0).array().round() / 1000.0;
    }
    ScheduleParameters parameters = bestPreset();
    parameters.despike = true;
    auto result = schedule(input, parameters);
    ASSERT_TRUE(result.has_value());
    const bool reported =
        std::any_of(result->warnings.begin(), result->warnings.end(),
                    [](const std::string& w) { return w.find("despiking changed") != w.npos; });
    EXPECT_TRUE(reported);
    expectMonotoneInsideTheChannel(*result);
}

// §4.5 adjust = shift in the pipeline: the same invariants as the recursive default.
TEST(ChannelOptions, ShiftAdjustmentKeepsThePipelineInvariants) {
    ScheduleParameters parameters = bestPreset();
    parameters.adjust = Adjust::Shift;
    auto result = schedule(helix(3.0), parameters);
    ASSERT_TRUE(result.has_value());
    expectMonotoneInsideTheChannel(*result);
    for (std::size_t k = 1; k + 1 < result->layers.size(); ++k) {
        EXPECT_NEAR(result->layers[k].dTheta.front(), 0.0, 1e-9);
        EXPECT_NEAR(result->layers[k].dTheta.back(), 0.0, 1e-9);
    }
}

} // namespace
} // namespace bladeaxis::scheduling

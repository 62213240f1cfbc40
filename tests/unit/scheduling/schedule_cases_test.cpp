// Spec §10.2 invariants 6-8, 11 and §10.3 degenerate and failure cases, plus the Appendix B
// numbers re-established on the synthetic section.
#include "core/base/units.h"
#include "core/scheduling/schedule.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
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

ScheduleInput helix(double revolutions, bool mirror = false) {
    testing::HelixOptions options;
    options.revolutions = revolutions;
    options.mirror = mirror;
    return testing::helicalPath(testing::appendixBCurve(), options);
}

TEST(ScheduleCases, InvalidInputIsAnErrorNotACrash) {
    ScheduleInput empty;
    empty.toolRadius = 8.0;
    EXPECT_EQ(schedule(empty, bestPreset()).error().code, ErrorCode::InvalidArgument);
    ScheduleInput one;
    one.centres = {Vec3(0, 1, 2)};
    one.axes = {Vec3(0, 0, 1)};
    one.toolRadius = 8.0;
    EXPECT_EQ(schedule(one, bestPreset()).error().code, ErrorCode::Geometry);
    ScheduleInput nan = helix(1.0);
    nan.centres[7].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(schedule(nan, bestPreset()).error().code, ErrorCode::Geometry);
    ScheduleInput mismatched = helix(1.0);
    mismatched.axes.pop_back();
    EXPECT_EQ(schedule(mismatched, bestPreset()).error().code, ErrorCode::InvalidArgument);
    ScheduleInput noRadius = helix(1.0);
    noRadius.toolRadius = 0.0;
    EXPECT_EQ(schedule(noRadius, bestPreset()).error().code, ErrorCode::InvalidArgument);
    ScheduleInput same;
    same.centres.assign(5, Vec3(0, 1, 2));
    same.axes.assign(5, Vec3::UnitZ());
    same.toolRadius = 8.0;
    EXPECT_FALSE(schedule(same, bestPreset()).has_value());
    ScheduleParameters bad = bestPreset();
    bad.marginRad = -1.0;
    EXPECT_EQ(schedule(helix(1.0), bad).error().code, ErrorCode::InvalidArgument);
}

TEST(ScheduleCases, LayerCountFollowsTheRevolutions) {
    for (double revolutions : {2.0, 5.0}) {
        auto result = schedule(helix(revolutions), bestPreset());
        ASSERT_TRUE(result.has_value());
        EXPECT_NEAR(static_cast<double>(result->basePoints.size()), revolutions, 1.0);
        EXPECT_EQ(result->check.reversals, 0u);
    }
}

TEST(ScheduleCases, ShorterThanOneRevolutionStillSchedules) {
    auto result = schedule(helix(0.6), bestPreset());
    ASSERT_TRUE(result.has_value());
    EXPECT_LE(result->layers.size(), 2u);
    EXPECT_EQ(result->check.reversals, 0u);
    EXPECT_TRUE(result->check.passes());
}

TEST(ScheduleCases, MirroredFeedFlipsTheTraversalAndKeepsRelativeResults) {
    auto a = schedule(helix(3.0), bestPreset());
    auto b = schedule(helix(3.0, true), bestPreset());
    ASSERT_TRUE(a.has_value() && b.has_value());
    EXPECT_EQ(a->traversalSign, -b->traversalSign);
    ASSERT_EQ(a->layers.size(), b->layers.size());
    for (std::size_t k = 0; k < a->layers.size(); ++k) {
        ASSERT_EQ(a->layers[k].theta.size(), b->layers[k].theta.size());
        for (std::size_t i = 0; i < a->layers[k].theta.size(); ++i) {
            EXPECT_NEAR(a->layers[k].theta[i], b->layers[k].theta[i], 1e-9);
            EXPECT_NEAR(a->layers[k].thetaMax[i], b->layers[k].thetaMax[i], 1e-9);
        }
    }
}

TEST(ScheduleCases, RotationAboutTheAxisShiftsOnlyTheAbsoluteAngle) {
    const ScheduleInput input = helix(3.0);
    ScheduleInput rotated = input;
    const double phi = 0.9;
    for (std::size_t i = 0; i < input.centres.size(); ++i) {
        rotated.centres[i] = rotationX(phi) * input.centres[i];
        rotated.axes[i] = rotationX(phi) * input.axes[i];
    }
    auto a = schedule(input, bestPreset());
    auto b = schedule(rotated, bestPreset());
    ASSERT_TRUE(a.has_value() && b.has_value());
    ASSERT_EQ(a->layers.size(), b->layers.size());
    for (std::size_t k = 1; k + 1 < a->layers.size(); ++k) { // intermediate layers
        for (std::size_t i = 0; i < a->layers[k].theta.size(); ++i) {
            EXPECT_NEAR(a->layers[k].theta[i], b->layers[k].theta[i], 1e-9);
        }
    }
    const std::vector<double> before = absoluteAngles(*a, Orientation::Rescheduled);
    const std::vector<double> after = absoluteAngles(*b, Orientation::Rescheduled);
    for (std::size_t i = 0; i < input.centres.size(); i += 50) {
        const double shift = after[i] - before[i];
        EXPECT_NEAR(std::remainder(shift - phi, 2.0 * kPi), 0.0, 1e-9); // feed turns about +x
    }
}

TEST(ScheduleCases, RunningOnItsOwnOutputReproducesIntermediateLayers) {
    const ScheduleInput input = helix(3.0);
    auto first = schedule(input, bestPreset());
    ASSERT_TRUE(first.has_value());
    ScheduleInput again = input;
    again.axes = first->newAxes;
    auto second = schedule(again, bestPreset());
    ASSERT_TRUE(second.has_value());
    ASSERT_EQ(first->layers.size(), second->layers.size());
    for (std::size_t k = 1; k + 1 < first->layers.size(); ++k) {
        for (std::size_t i = 0; i < first->layers[k].theta.size(); ++i) {
            EXPECT_NEAR(first->layers[k].theta[i], second->layers[k].theta[i], 1e-9);
        }
    }
    EXPECT_EQ(second->originalReversals, 0u);
}

TEST(ScheduleCases, DuplicatePointsAreMergedAndShareTheirOrientation) {
    const ScheduleInput input = helix(2.0);
    ScheduleInput doubled;
    doubled.toolRadius = input.toolRadius;
    for (std::size_t i = 0; i < input.centres.size(); ++i) {
        const int copies = i % 10 == 0 ? 2 : 1;
        for (int c = 0; c < copies; ++c) {
            doubled.centres.push_back(input.centres[i]);
            doubled.axes.push_back(input.axes[i]);
        }
    }
    auto a = schedule(input, bestPreset());
    auto b = schedule(doubled, bestPreset());
    ASSERT_TRUE(a.has_value() && b.has_value());
    EXPECT_EQ(b->newAxes.size(), doubled.centres.size());
    EXPECT_FALSE(b->warnings.empty());
    const std::vector<double> single = absoluteAngles(*a, Orientation::Rescheduled);
    const std::vector<double> doubledAngles = absoluteAngles(*b, Orientation::Rescheduled);
    std::size_t j = 0;
    for (std::size_t i = 0; i < input.centres.size(); ++i) {
        const int copies = i % 10 == 0 ? 2 : 1;
        for (int c = 0; c < copies; ++c, ++j) {
            EXPECT_NEAR(doubledAngles[j], single[i], 1e-12);
        }
    }
}

TEST(ScheduleCases, SymmetricSectionUsesTheFallbackBasePoint) {
    testing::HelixOptions options;
    options.revolutions = 3.0;
    const testing::OffsetCurve curve = testing::offsetSection(
        testing::nacaSection(0.0, 0.4, 0.12, 80.0, 121), 8.0, units::degToRad(5.0));
    auto result = schedule(testing::helicalPath(curve, options), bestPreset());
    ASSERT_TRUE(result.has_value());
    EXPECT_GE(result->basePoints.size(), 2u);
    bool fallback = false;
    for (const LayerResult& layer : result->layers) {
        fallback = fallback || hasFlag(layer, LayerStatus::NoConcaveRun);
    }
    EXPECT_TRUE(fallback);
    EXPECT_EQ(result->check.reversals, 0u);
}

TEST(ScheduleCases, TaperNearNinetyDegreesIsMonotoneInfeasibleAndKeepsTheOriginal) {
    const ScheduleInput input = helix(2.0);
    ScheduleParameters parameters = bestPreset();
    parameters.taperHalfAngleRad = units::degToRad(85.0); // width pi + tau - 170 deg < 0 in places
    auto result = schedule(input, parameters);
    ASSERT_TRUE(result.has_value());
    std::size_t infeasible = 0;
    for (std::size_t k = 0; k < result->layers.size(); ++k) {
        const LayerResult& layer = result->layers[k];
        if (hasFlag(layer, LayerStatus::MonotoneInfeasible)) {
            ++infeasible;
            std::vector<std::size_t> own = layer.inputIndex;
            if (k + 1 < result->layers.size()) {
                own.pop_back(); // the shared end sample belongs to the next layer
            }
            for (std::size_t input_i : own) {
                EXPECT_NEAR((result->newAxes[input_i] - input.axes[input_i].normalized()).norm(),
                            0.0, 1e-15);
            }
        }
    }
    EXPECT_GT(infeasible, 0u);
    EXPECT_FALSE(result->warnings.empty());
    // §6.5 junction gaps: measured at every base point, and any step is reported.
    double largest = 0.0;
    for (std::size_t k = 0; k + 1 < result->layers.size(); ++k) {
        const LayerResult& a = result->layers[k];
        const LayerResult& b = result->layers[k + 1];
        largest = std::max(largest, std::abs(a.junctionAngle + a.theta.back() - b.junctionAngle -
                                             b.theta.front()));
    }
    EXPECT_DOUBLE_EQ(result->check.maxJunctionGapRad, largest);
    const bool stepReported = std::ranges::any_of(result->warnings, [](const std::string& w) {
        return w.find("orientation steps by") != std::string::npos;
    });
    EXPECT_EQ(stepReported, largest > 1e-9);
}

// Parameters under which some layers keep the original orientation (MonotoneInfeasible), so
// the input's axes are read at the assembly too.
ScheduleParameters parametersKeepingSomeLayers() {
    ScheduleParameters parameters = bestPreset();
    parameters.taperHalfAngleRad = units::degToRad(85.0);
    return parameters;
}

void expectTheSameSchedule(const ScheduleResult& actual, const ScheduleResult& expected) {
    EXPECT_EQ(actual.newAxes, expected.newAxes);
    ASSERT_EQ(actual.layers.size(), expected.layers.size());
    for (std::size_t k = 0; k < expected.layers.size(); ++k) {
        EXPECT_EQ(actual.layers[k].theta, expected.layers[k].theta) << k;
        EXPECT_EQ(actual.layers[k].flags, expected.layers[k].flags) << k;
    }
    EXPECT_EQ(actual.originalReversals, expected.originalReversals);
    EXPECT_EQ(actual.check.maxCentreErrorMm, expected.check.maxCentreErrorMm);
    EXPECT_EQ(actual.check.maxUnitError, expected.check.maxUnitError);
    EXPECT_EQ(actual.check.maxTiltError, expected.check.maxTiltError);
}

// The stages run one by one over a toolpath's records, each ball centre made from its tip and
// axis as it is read (as a job reads its program), give the schedule of one call over arrays of
// those centres; the layers that keep the original orientation read their axes again.
TEST(ScheduleCases, TheStagesOneByOneOverRecordsGiveTheScheduleOfOneCall) {
    const ScheduleParameters parameters = parametersKeepingSomeLayers();
    const ScheduleInput helixInput = helix(2.0);
    struct Record {
        Vec3 tip;
        Vec3 axis;
        int line = 0;
    };
    std::vector<Record> records;
    ScheduleInput input{
        .centres = {}, .axes = helixInput.axes, .toolRadius = helixInput.toolRadius};
    for (std::size_t i = 0; i < helixInput.centres.size(); ++i) {
        const Vec3& axis = helixInput.axes[i];
        records.push_back({helixInput.centres[i] - input.toolRadius * axis.normalized(), axis,
                           static_cast<int>(i)});
        input.centres.push_back(records.back().tip + input.toolRadius * axis.normalized());
    }
    const auto whole = schedule(input, parameters);
    ASSERT_TRUE(whole.has_value()) << whole.error().toString();
    const bool someLayerKeepsTheOriginal =
        std::ranges::any_of(whole->layers, [](const LayerResult& layer) {
            return std::ranges::find(layer.flags, LayerStatus::MonotoneInfeasible) !=
                   layer.flags.end();
        });
    ASSERT_TRUE(someLayerKeepsTheOriginal);

    const std::span<const Record> view(records);
    const ScheduleSamples samples{.points = Vec3Run(view, &Record::tip),
                                  .axes = Vec3Run(view, &Record::axis),
                                  .toolRadius = input.toolRadius,
                                  .pointsAreTips = true};
    auto path = makePlanePath(samples, parameters);
    ASSERT_TRUE(path.has_value()) << path.error().toString();
    auto plan = planLayers(std::move(*path), samples, parameters, nullptr);
    ASSERT_TRUE(plan.has_value()) << plan.error().toString();
    const auto staged = scheduleLayers(std::move(*plan), samples, parameters, nullptr);
    ASSERT_TRUE(staged.has_value()) << staged.error().toString();
    expectTheSameSchedule(*staged, *whole);
}

TEST(ScheduleCases, NoisyCoordinatesStillGiveAMonotoneSchedule) {
    ScheduleInput input = helix(3.0);
    for (Vec3& q : input.centres) { // rounding to 1e-3 mm imitates G-code
        q = (q * 1000.0).array().round() / 1000.0;
    }
    auto result = schedule(input, bestPreset());
    ASSERT_TRUE(result.has_value());
    EXPECT_EQ(result->check.reversals, 0u);
    EXPECT_TRUE(result->check.passes());
    EXPECT_EQ(result->layers.size(), 4u);
}

TEST(ScheduleCases, CancelledRunReturnsCancelled) {
    CancelToken token;
    token.requestCancel();
    auto result = schedule(helix(2.0), bestPreset(), &token);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

// A cancel that comes while the stages before the layers run ends the schedule at the next
// stage, not after every layer's turn to look at the token.
TEST(ScheduleCases, ACancelBeforeTheLayersEndsTheRunWithCancelled) {
    CancelToken token;
    const ScheduleInput input = helix(2.0);
    const ScheduleSamples samples = samplesOf(input);
    auto path = makePlanePath(samples, bestPreset());
    ASSERT_TRUE(path.has_value());
    token.requestCancel();
    auto plan = planLayers(*path, samples, bestPreset(), &token);
    ASSERT_FALSE(plan.has_value());
    EXPECT_EQ(plan.error().code, ErrorCode::Cancelled);

    auto uncancelled = planLayers(std::move(*path), samples, bestPreset(), nullptr);
    ASSERT_TRUE(uncancelled.has_value());
    auto layers = scheduleLayers(std::move(*uncancelled), samples, bestPreset(), &token);
    ASSERT_FALSE(layers.has_value());
    EXPECT_EQ(layers.error().code, ErrorCode::Cancelled);
}

// Appendix B re-established: layer length 217.5 mm, theta_e = 2 pi, and the peak theta'' of
// the paper rule vs the exact rule (table of Appendix B, within 5 %).
TEST(ScheduleCases, AppendixBNumbers) {
    const ScheduleInput input = helix(3.0);
    ScheduleParameters paper = faithfulPreset();
    const std::pair<double, double> table[] = {{0.05, 0.0064}, {0.10, 0.0082}, {0.20, 0.0144}};
    for (const auto& [rho, peak] : table) {
        paper.leadFraction = rho;
        auto result = schedule(input, paper);
        ASSERT_TRUE(result.has_value());
        const LayerResult& layer = result->layers[1];
        EXPECT_NEAR(layer.s.back(), 217.5, 0.5);
        EXPECT_NEAR(layer.theta.back(), 2.0 * kPi, 1e-9);
        EXPECT_NEAR(layer.peakSecondDerivative, peak, 0.05 * peak) << rho;
    }
    const auto started = std::chrono::steady_clock::now();
    auto best = schedule(input, bestPreset());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    ASSERT_TRUE(best.has_value());
    EXPECT_LT(best->layers[1].peakSecondDerivative, 0.0016); // Appendix B: 0.00149 at rho 0.2
    std::printf("[ measure  ] Appendix B helix: %zu points in %.4f s (%.0f points/s), peak "
                "theta'' exact/auto %.5f rad/mm^2 at rho %.3f\n",
                input.centres.size(), seconds, static_cast<double>(input.centres.size()) / seconds,
                best->layers[1].peakSecondDerivative, best->layers[1].leadFraction);
}

} // namespace
} // namespace bladeaxis::scheduling

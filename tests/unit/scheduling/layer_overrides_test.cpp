// Per-layer overrides (the engineer's edits kept with a job): they change their own layer,
// leave the layers that do not touch it alone, and refuse edits that do not fit.
#include "core/scheduling/layer_edit.h"
#include "core/scheduling/schedule.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <vector>

namespace bladeaxis::scheduling {
namespace {

ScheduleInput fiveRevolutionHelix() {
    testing::HelixOptions options;
    options.revolutions = 5.0;
    return testing::helicalPath(testing::appendixBCurve(), options);
}

// The engine's polyline of `layer` with one interior key point moved a little inside the hull.
std::vector<Vec2> nudgedKeyPoints(const LayerResult& layer) {
    for (const double step : {0.02, -0.02, 0.01, -0.01, 0.005, -0.005}) {
        for (std::size_t v = 1; v + 1 < layer.polyline.size(); ++v) {
            std::vector<Vec2> points = layer.polyline;
            points[v].y() += step;
            if (resmoothLayer(layer, points, bestPreset())) {
                return points;
            }
        }
    }
    return {};
}

TEST(LayerOverrides, KeyPointEditReplacesOnlyItsLayer) {
    const ScheduleInput input = fiveRevolutionHelix();
    const auto plain = schedule(input, bestPreset());
    ASSERT_TRUE(plain.has_value()) << plain.error().toString();
    ASSERT_GE(plain->layers.size(), 4u);
    const std::size_t edited = 2;
    LayerOverride edit;
    edit.layer = edited;
    edit.keyPoints = nudgedKeyPoints(plain->layers[edited]);
    ASSERT_FALSE(edit.keyPoints.empty()) << "no interior key point can move in layer 2";

    const auto changed = schedule(input, bestPreset(), nullptr, std::vector{edit});
    ASSERT_TRUE(changed.has_value()) << changed.error().toString();
    const auto expected = resmoothLayer(plain->layers[edited], edit.keyPoints, bestPreset());
    ASSERT_TRUE(expected.has_value());
    EXPECT_EQ(changed->layers[edited].theta, expected->theta);
    EXPECT_NE(changed->layers[edited].theta, plain->layers[edited].theta);
    for (std::size_t k = 0; k < plain->layers.size(); ++k) {
        if (k != edited) {
            EXPECT_EQ(changed->layers[k].theta, plain->layers[k].theta) << "layer " << k;
        }
    }
    EXPECT_EQ(changed->check.reversals, 0u);
    EXPECT_TRUE(changed->check.passes());
}

// The editor's re-smoothing of the engine's own key points gives the engine's curve: an undo to
// the unedited polyline shows exactly what the job schedules.
TEST(LayerOverrides, ResmoothingTheEnginesKeyPointsReproducesItsCurve) {
    const ScheduleInput input = fiveRevolutionHelix();
    for (const ScheduleParameters& parameters : {bestPreset(), faithfulPreset()}) {
        const auto plain = schedule(input, parameters);
        ASSERT_TRUE(plain.has_value());
        for (std::size_t k = 0; k < plain->layers.size(); ++k) {
            const LayerResult& layer = plain->layers[k];
            const auto again = resmoothLayer(layer, layer.polyline, parameters);
            ASSERT_TRUE(again.has_value()) << again.error().toString();
            ASSERT_EQ(again->theta.size(), layer.theta.size());
            for (std::size_t i = 0; i < layer.theta.size(); ++i) {
                ASSERT_NEAR(again->theta[i], layer.theta[i], 1e-12) << "layer " << k << " " << i;
            }
        }
    }
}

TEST(LayerOverrides, MarginChangesItsLayerAndAtMostTheNeighboursJunctions) {
    const ScheduleInput input = fiveRevolutionHelix();
    const auto plain = schedule(input, bestPreset());
    ASSERT_TRUE(plain.has_value());
    const std::size_t edited = 2;
    LayerOverride edit;
    edit.layer = edited;
    edit.marginRad = 0.25 * bestPreset().marginRad;
    const auto changed = schedule(input, bestPreset(), nullptr, std::vector{edit});
    ASSERT_TRUE(changed.has_value()) << changed.error().toString();
    EXPECT_NE(changed->layers[edited].lo, plain->layers[edited].lo);
    for (std::size_t k = 0; k < plain->layers.size(); ++k) {
        if (k + 1 < edited || k > edited + 1) { // the junctions J_k, J_k+1 are shared
            EXPECT_EQ(changed->layers[k].theta, plain->layers[k].theta) << "layer " << k;
        }
    }
}

TEST(LayerOverrides, PresetAndLeadFractionApplyToTheirLayerOnly) {
    const ScheduleInput input = fiveRevolutionHelix();
    LayerOverride edit;
    edit.layer = 1;
    edit.preset = Preset::Faithful;
    edit.leadFraction = 0.3;
    const auto changed = schedule(input, bestPreset(), nullptr, std::vector{edit});
    ASSERT_TRUE(changed.has_value()) << changed.error().toString();
    EXPECT_DOUBLE_EQ(changed->layers[1].leadFraction, 0.3);
    const ScheduleParameters resolved = layerParameters(bestPreset(), edit);
    EXPECT_EQ(resolved.epsilonRule, faithfulPreset().epsilonRule);
    EXPECT_EQ(resolved.cornerForm, faithfulPreset().cornerForm);
    EXPECT_EQ(resolved.leadMode, LeadMode::Fixed);
    EXPECT_EQ(resolved.tangentChordMinMm, bestPreset().tangentChordMinMm); // channel-wide
}

TEST(LayerOverrides, EditOfAMissingLayerIsRefused) {
    LayerOverride edit;
    edit.layer = 999;
    edit.marginRad = 0.01;
    const auto result = schedule(fiveRevolutionHelix(), bestPreset(), nullptr, std::vector{edit});
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("layer 999"), std::string::npos);
}

TEST(LayerOverrides, LayerEditedTwiceIsRefused) {
    LayerOverride edit;
    edit.layer = 1;
    edit.marginRad = 0.01;
    const auto result =
        schedule(fiveRevolutionHelix(), bestPreset(), nullptr, std::vector{edit, edit});
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("twice"), std::string::npos);
}

TEST(LayerOverrides, InvalidLayerSettingIsRefusedNamingTheLayer) {
    LayerOverride edit;
    edit.layer = 1;
    edit.leadFraction = 0.9; // rho must stay below one half
    const auto result = schedule(fiveRevolutionHelix(), bestPreset(), nullptr, std::vector{edit});
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("layer 1"), std::string::npos);
}

TEST(LayerOverrides, KeyPointsOutsideTheChannelFailTheScheduleNamingTheLayer) {
    const ScheduleInput input = fiveRevolutionHelix();
    const auto plain = schedule(input, bestPreset());
    ASSERT_TRUE(plain.has_value());
    LayerOverride edit;
    edit.layer = 2;
    edit.keyPoints = plain->layers[2].polyline;
    ASSERT_GE(edit.keyPoints.size(), 3u);
    edit.keyPoints[1].y() += 3.0; // far above the hull
    const auto result = schedule(input, bestPreset(), nullptr, std::vector{edit});
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("layer 2"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::scheduling

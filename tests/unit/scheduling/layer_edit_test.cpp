// resmoothLayer: edits inside the hull re-smooth the layer; edits that break monotonicity,
// leave the hull or move the ends are refused.

#include "core/scheduling/layer_edit.h"

#include <gtest/gtest.h>

#include <vector>

namespace bladeaxis::scheduling {
namespace {

// A straight channel of half-width 0.3 rad rising 0.01 rad/mm over 100 mm, scheduled as the
// straight line from (0, 0) to (100, 1).
LayerResult straightChannelLayer() {
    LayerResult layer;
    for (int i = 0; i <= 100; ++i) {
        const double s = static_cast<double>(i);
        layer.s.push_back(s);
        layer.thetaOriginal.push_back(0.01 * s);
        layer.thetaMin.push_back(0.01 * s - 0.3);
        layer.thetaMax.push_back(0.01 * s + 0.3);
        layer.theta.push_back(0.01 * s);
    }
    layer.lo = layer.thetaMin;
    layer.hi = layer.thetaMax;
    layer.last = 100;
    layer.polyline = {Vec2(0.0, 0.0), Vec2(100.0, 1.0)};
    layer.keyPoints = layer.polyline;
    return layer;
}

bool isMonotoneNonDecreasing(const std::vector<double>& values) {
    for (std::size_t i = 1; i < values.size(); ++i) {
        if (values[i] < values[i - 1] - 1e-12) {
            return false;
        }
    }
    return true;
}

TEST(LayerEdit, KeyPointInsideTheHullBendsTheCurveAndKeepsItInTheChannel) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.0}, {50.0, 0.7}, {100.0, 1.0}};
    const Result<LayerResult> edited = resmoothLayer(layer, edit, bestPreset());
    ASSERT_TRUE(edited.has_value()) << edited.error().toString();
    ASSERT_EQ(edited->theta.size(), layer.s.size());
    EXPECT_GT(edited->theta[50], layer.theta[50] + 0.05);
    EXPECT_TRUE(isMonotoneNonDecreasing(edited->theta));
    for (std::size_t i = 0; i < edited->theta.size(); ++i) {
        EXPECT_GE(edited->theta[i], layer.thetaMin[i]);
        EXPECT_LE(edited->theta[i], layer.thetaMax[i]);
    }
    EXPECT_GT(edited->minClearance, 0.0);
    EXPECT_EQ(edited->polyline.size(), edit.size());
    EXPECT_DOUBLE_EQ(edited->theta.front(), 0.0);
    EXPECT_DOUBLE_EQ(edited->theta.back(), 1.0);
}

TEST(LayerEdit, KeyPointSnapsToTheNearestSample) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.0}, {49.7, 0.6}, {100.0, 1.0}};
    const Result<LayerResult> edited = resmoothLayer(layer, edit, bestPreset());
    ASSERT_TRUE(edited.has_value()) << edited.error().toString();
    EXPECT_DOUBLE_EQ(edited->polyline[1].x(), 50.0);
}

TEST(LayerEdit, NonMonotoneEditIsRefused) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.0}, {30.0, 0.5}, {60.0, 0.35}, {100.0, 1.0}};
    const Result<LayerResult> edited = resmoothLayer(layer, edit, bestPreset());
    ASSERT_FALSE(edited.has_value());
    EXPECT_EQ(edited.error().code, ErrorCode::InvalidArgument);
    // Named as the editor's table counts them, with the amount in degrees: 0.15 rad back.
    EXPECT_EQ(edited.error().message, "key point 3 turns theta(S) back by 8.59 deg from key "
                                      "point 2: the rotary axis would reverse");
}

TEST(LayerEdit, KeyPointOutsideTheHullIsRefused) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.0}, {50.0, 0.85}, {100.0, 1.0}};
    const Result<LayerResult> edited = resmoothLayer(layer, edit, bestPreset());
    ASSERT_FALSE(edited.has_value());
    EXPECT_NE(edited.error().message.find("channel"), std::string::npos);
}

TEST(LayerEdit, MovingAnEndIsRefused) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.1}, {50.0, 0.5}, {100.0, 1.0}};
    EXPECT_FALSE(resmoothLayer(layer, edit, bestPreset()).has_value());
}

TEST(LayerEdit, KeyPointsOnTheSameSampleAreRefused) {
    const LayerResult layer = straightChannelLayer();
    const std::vector<Vec2> edit{{0.0, 0.0}, {50.0, 0.5}, {50.2, 0.55}, {100.0, 1.0}};
    EXPECT_FALSE(resmoothLayer(layer, edit, bestPreset()).has_value());
}

} // namespace
} // namespace bladeaxis::scheduling

// Spec §1.7: base points, one per revolution, at the main concave run's altered point and then
// at the best candidate one revolution on.
#include "core/scheduling/layers.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

// Four revolutions of 100 samples, the tangent turning evenly.
std::vector<double> fourRevolutions() {
    std::vector<double> phi(400);
    for (std::size_t i = 0; i < phi.size(); ++i) {
        phi[i] = 2.0 * kPi * static_cast<double>(i) / 100.0;
    }
    return phi;
}

ConcaveRun runAt(std::size_t entry, double lengthMm) {
    return {entry, entry + 5, lengthMm, 0.1};
}

TEST(LayerSplit, BasePointsFollowTheMainRunARevolutionApart) {
    const std::vector<double> phi = fourRevolutions();
    const std::vector<double> flat(phi.size(), 0.0);
    const std::vector<ConcaveRun> runs = {runAt(20, 10.0), runAt(110, 4.0), runAt(130, 6.0),
                                          runAt(220, 5.0), runAt(320, 5.0)};
    const LayerSplit split = splitLayers(phi, flat, runs, BasePointRule::Entry);
    EXPECT_EQ(split.basePoints, (std::vector<std::size_t>{20, 130, 220, 320}));
    EXPECT_EQ(split.fallback, (std::vector<bool>{false, false, false, false}));
    ASSERT_EQ(split.layers.size(), 5u);
    EXPECT_EQ(split.layers.front().first, 0u);
    EXPECT_EQ(split.layers.back().last, 399u);
}

TEST(LayerSplit, OfEqualCandidatesTheFirstAlongThePathIsTaken) {
    // Sample 120 turns back below sample 100: the later candidate has the smaller angle.
    std::vector<double> phi = fourRevolutions();
    phi[120] = phi[100] - 0.05;
    const std::vector<double> flat(phi.size(), 0.0);
    const std::vector<ConcaveRun> runs = {runAt(20, 10.0), runAt(100, 5.0), runAt(120, 5.0),
                                          runAt(220, 5.0), runAt(320, 5.0)};
    const LayerSplit split = splitLayers(phi, flat, runs, BasePointRule::Entry);
    EXPECT_EQ(split.basePoints, (std::vector<std::size_t>{20, 100, 220, 320}));
}

TEST(LayerSplit, OfEqualMainRunsTheFirstAlongThePathAnchors) {
    // Two runs as long and as turning as each other, the later one at a smaller angle: the
    // anchor is the first, and the walk back from it finds nothing a revolution before.
    std::vector<double> phi = fourRevolutions();
    phi[250] = phi[30] - 0.01;
    const std::vector<double> flat(phi.size(), 0.0);
    const std::vector<ConcaveRun> runs = {runAt(30, 10.0), runAt(250, 10.0)};
    const LayerSplit split = splitLayers(phi, flat, runs, BasePointRule::Entry);
    ASSERT_FALSE(split.basePoints.empty());
    EXPECT_EQ(split.basePoints.front(), 30u);
    EXPECT_FALSE(split.fallback.front());
}

} // namespace
} // namespace bladeaxis::scheduling

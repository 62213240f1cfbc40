// Spec §2.5, §3.1, §3.3 and §6.5: how layer problems are set up around a layer that keeps its
// original orientation (MONOTONE_INFEASIBLE).
#include "core/scheduling/layer_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bladeaxis::scheduling {
namespace {

constexpr double kSlope = 0.3; // rad per sample of the rising channel
constexpr std::size_t kSamples = 31;

bool hasFlag(const LayerProblem& problem, LayerStatus status) {
    return std::find(problem.flags.begin(), problem.flags.end(), status) != problem.flags.end();
}

// Three layers [0, 10], [10, 20], [20, 30] of a channel 2 rad wide rising with the input
// orientation in its middle; layer 1 is pinched beyond repair: its lower limit at sample 12
// lies above its upper limit at sample 14, so no monotone path exists there.
struct ThreeLayers {
    PlanePath path;
    RawChannel channel;
    LayerSplit split;

    ThreeLayers() {
        for (std::size_t i = 0; i < kSamples; ++i) {
            const double middle = kSlope * static_cast<double>(i);
            path.arcLength.push_back(static_cast<double>(i));
            path.originalAngle.push_back(std::remainder(middle, 2.0 * std::numbers::pi));
            channel.thetaMin.push_back(middle - 1.0);
            channel.thetaMax.push_back(middle + 1.0);
        }
        channel.thetaMin[12] = kSlope * 14 + 0.5;
        split.basePoints = {10, 20};
        split.fallback = {false, false};
        split.layers = {{0, 10, true, false, false}, {10, 20}, {20, 30, false, true, false}};
    }
};

TEST(LayerProblems, NeighboursOfAKeptLayerMeetItsOriginalOrientation) {
    const ThreeLayers setup;
    const std::vector<double> margins(3, 0.0);
    const auto problems = buildLayerProblems(setup.path, setup.channel, setup.split, margins, 1.0);
    ASSERT_EQ(problems.size(), 3u);
    ASSERT_TRUE(hasFlag(problems[1], LayerStatus::MonotoneInfeasible));
    EXPECT_FALSE(hasFlag(problems[0], LayerStatus::MonotoneInfeasible));
    EXPECT_FALSE(hasFlag(problems[2], LayerStatus::MonotoneInfeasible));

    // The kept layer's orientation at both base points is the input's.
    const double keptStart = problems[1].reference + problems[1].original.front();
    const double keptEnd = problems[1].reference + problems[1].original.back();
    EXPECT_NEAR(keptStart, kSlope * 10, 1e-12);
    EXPECT_NEAR(keptEnd, kSlope * 20, 1e-12);
    // Its neighbours end and start there, as free ends, instead of at the junction angles.
    EXPECT_TRUE(problems[0].span.endFree);
    EXPECT_TRUE(problems[2].span.startFree);
    EXPECT_NEAR(problems[0].reference + problems[0].endValue, keptStart, 1e-12);
    EXPECT_NEAR(problems[2].reference + problems[2].startValue, keptEnd, 1e-12);
    const auto& warnings = problems.front().warnings;
    EXPECT_TRUE(std::ranges::any_of(warnings, [](const std::string& w) {
        return w.find("original orientation of the kept layer 1") != std::string::npos;
    }));
}

TEST(LayerProblems, WithoutAKeptLayerTheLayersMeetAtTheJunctionAngles) {
    ThreeLayers setup;
    setup.channel.thetaMin[12] = kSlope * 12 - 1.0; // the pinch removed
    const std::vector<double> margins(3, 0.0);
    const auto problems = buildLayerProblems(setup.path, setup.channel, setup.split, margins, 1.0);
    ASSERT_EQ(problems.size(), 3u);
    for (const LayerProblem& problem : problems) {
        EXPECT_FALSE(hasFlag(problem, LayerStatus::MonotoneInfeasible));
    }
    EXPECT_FALSE(problems[0].span.endFree);
    EXPECT_FALSE(problems[2].span.startFree);
    EXPECT_NEAR(problems[0].reference + problems[0].endValue, problems[1].reference, 1e-12);
    EXPECT_NEAR(problems[1].reference + problems[1].endValue, problems[2].reference, 1e-12);
}

} // namespace
} // namespace bladeaxis::scheduling

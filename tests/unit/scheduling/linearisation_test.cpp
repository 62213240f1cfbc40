// Spec §10.1 row "linearisation" (§3.4, §4).
#include "core/scheduling/channel.h"
#include "core/scheduling/linearisation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

struct Layer {
    std::vector<double> s, lo, hi;
};

// A wide, smooth channel rising by 2 pi over 200 mm, flat at both ends (an intermediate layer).
Layer wideLayer(std::size_t n = 401) {
    Layer layer;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = 200.0 * static_cast<double>(i) / static_cast<double>(n - 1);
        const double centre = kPi * (1.0 - std::cos(kPi * s / 200.0));
        layer.s.push_back(s);
        layer.lo.push_back(std::max(0.0, centre - 2.0) - (s < 1e-9 ? 0.1 : 0.0));
        layer.hi.push_back(std::min(2.0 * kPi, centre + 2.0));
    }
    return layer;
}

// A wiggly channel: hull of a random raw channel, narrow enough to need key points.
Layer wigglyLayer(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> noise(-0.3, 0.3);
    std::vector<double> s, rawLo, rawHi;
    for (std::size_t i = 0; i < 300; ++i) {
        const double x = static_cast<double>(i);
        const double centre = 2.0 * kPi * x / 299.0 + 0.8 * std::sin(x / 17.0);
        s.push_back(x);
        rawLo.push_back(centre - 0.7 + noise(random));
        rawHi.push_back(centre + 0.7 + noise(random));
    }
    for (std::size_t i = 0; i < 30; ++i) { // room for the leads: open ends
        rawLo[i] = -100.0;
        rawHi[299 - i] = 100.0;
    }
    const MonotoneHull hull = monotoneHull(rawLo, rawHi, 0.0);
    return {s, hull.lo, hull.hi};
}

void expectValidPolyline(const std::vector<PolyVertex>& v, const Layer& layer) {
    for (std::size_t k = 1; k < v.size(); ++k) {
        EXPECT_GT(v[k].s, v[k - 1].s);
        EXPECT_GE(v[k].theta, v[k - 1].theta - 1e-12);
        EXPECT_TRUE(segmentInside(v[k - 1], v[k], layer.s, layer.lo, layer.hi, 1e-9));
    }
    for (const PolyVertex& x : v) {
        EXPECT_GE(x.theta, layer.lo[x.index] - 1e-9);
        EXPECT_LE(x.theta, layer.hi[x.index] + 1e-9);
    }
}

TEST(Linearisation, FeasibleStraightLeadRampLeadHasFourVertices) {
    const Layer layer = wideLayer();
    const LeadChoice leads =
        chooseLeads(layer.s, layer.lo, layer.hi, 0.0, 2.0 * kPi, 0.15, false, false, 1e-9);
    ASSERT_TRUE(leads.leadIn && leads.leadOut);
    EXPECT_NEAR(layer.s[*leads.leadIn], 30.0, 0.5);
    EXPECT_NEAR(layer.s[*leads.leadOut], 170.0, 0.5);
    const Linearisation lines =
        linearise({layer.s, layer.lo, layer.hi, 0.0, 2.0 * kPi, leads, KeyMode::Both, 1e-9});
    ASSERT_EQ(lines.vertices.size(), 4u);
    EXPECT_TRUE(lines.keyPoints.empty());
    EXPECT_EQ(lines.vertices[0].theta, lines.vertices[1].theta); // horizontal lead-in
    EXPECT_EQ(lines.vertices[2].theta, lines.vertices[3].theta); // horizontal lead-out
    expectValidPolyline(lines.vertices, layer);
}

TEST(Linearisation, LeadInStopsWhereTheStartValueLeavesTheHull) {
    const Layer layer = wideLayer();
    // lo exceeds 0 where centre > 2: 1 - cos(pi s / 200) > 2 / pi, s > 76.31 mm.
    const LeadChoice leads =
        chooseLeads(layer.s, layer.lo, layer.hi, 0.0, 2.0 * kPi, 0.45, false, false, 1e-9);
    EXPECT_LE(layer.s[*leads.leadIn], 76.31);
    EXPECT_GE(layer.s[*leads.leadIn], 75.8);
}

TEST(Linearisation, KeyPointsKeepThePolylineMonotoneAndInsideTheHull) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const Layer layer = wigglyLayer(seed);
        const double end = std::max(layer.lo.back(), 2.0 * kPi);
        for (KeyMode mode : {KeyMode::Both, KeyMode::Worst}) {
            const LeadChoice leads =
                chooseLeads(layer.s, layer.lo, layer.hi, 0.0, end, 0.1, false, false, 1e-9);
            const Linearisation lines =
                linearise({layer.s, layer.lo, layer.hi, 0.0, end, leads, mode, 1e-9});
            EXPECT_GT(lines.keyPoints.size(), 0u);
            EXPECT_EQ(lines.vertices.front().theta, 0.0);
            EXPECT_EQ(lines.vertices.back().theta, end);
            expectValidPolyline(lines.vertices, layer);
            const std::vector<PolyVertex> again =
                removeRedundant(lines.vertices, layer.s, layer.lo, layer.hi, 1e-9);
            ASSERT_EQ(again.size(), lines.vertices.size()); // idempotent
        }
    }
}

// §4.5 adjust = shift: keys moved off the hull boundary (Fig. 7b of the paper) where that makes
// both new segments feasible; the polyline keeps every invariant of the recursive mode.
TEST(Linearisation, ShiftModeMovesKeysInwardAndKeepsThePolylineValid) {
    std::size_t shifted = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const Layer layer = wigglyLayer(seed);
        const double end = std::max(layer.lo.back(), 2.0 * kPi);
        const LeadChoice leads =
            chooseLeads(layer.s, layer.lo, layer.hi, 0.0, end, 0.1, false, false, 1e-9);
        const Linearisation lines = linearise({layer.s, layer.lo, layer.hi, 0.0, end, leads,
                                               KeyMode::Worst, 1e-9, Adjust::Shift, 0.005});
        EXPECT_EQ(lines.vertices.front().theta, 0.0);
        EXPECT_EQ(lines.vertices.back().theta, end);
        expectValidPolyline(lines.vertices, layer);
        for (const PolyVertex& key : lines.keyPoints) {
            const bool onHull = std::abs(key.theta - layer.hi[key.index]) < 1e-12 ||
                                std::abs(key.theta - layer.lo[key.index]) < 1e-12;
            shifted += onHull ? 0 : 1;
        }
    }
    EXPECT_GT(shifted, 0u);
}

TEST(Linearisation, FreeEndsHaveNoLeadSegment) {
    const Layer layer = wideLayer();
    const LeadChoice leads =
        chooseLeads(layer.s, layer.lo, layer.hi, 0.0, 2.0 * kPi, 0.15, true, false, 1e-9);
    EXPECT_FALSE(leads.leadIn.has_value());
    EXPECT_TRUE(leads.leadOut.has_value());
    const Linearisation lines =
        linearise({layer.s, layer.lo, layer.hi, 0.0, 2.0 * kPi, leads, KeyMode::Both, 1e-9});
    EXPECT_EQ(lines.vertices.size(), 3u);
    EXPECT_EQ(lines.vertices[1].index, *leads.leadOut);
    expectValidPolyline(lines.vertices, layer);
}

} // namespace
} // namespace bladeaxis::scheduling

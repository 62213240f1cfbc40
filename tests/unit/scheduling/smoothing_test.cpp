// Spec §10.1 row "smoothing" (§5.4, §5.8): both epsilon rules, both corner forms and both
// graph-limit corner profiles.
#include "core/scheduling/channel.h"
#include "core/scheduling/linearisation.h"
#include "core/scheduling/smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

struct WigglyLayer {
    std::vector<double> s, rawLo, rawHi;
    MonotoneHull hull;
    Linearisation lines;
};

WigglyLayer wigglySetup(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> noise(-0.2, 0.2);
    WigglyLayer x;
    for (std::size_t i = 0; i < 400; ++i) {
        const double s = 0.5 * static_cast<double>(i);
        const double centre = 2.0 * kPi * s / 199.5 + 0.6 * std::sin(s / 11.0);
        x.s.push_back(s);
        x.rawLo.push_back(i < 40 ? -10.0 : centre - 0.8 + noise(random));
        x.rawHi.push_back(i >= 360 ? 10.0 : centre + 0.8 + noise(random));
    }
    x.hull = monotoneHull(x.rawLo, x.rawHi, 0.05);
    const double end = std::max(x.hull.lo.back(), 2.0 * kPi);
    const LeadChoice leads =
        chooseLeads(x.s, x.hull.lo, x.hull.hi, 0.0, end, 0.1, false, false, 1e-9);
    x.lines = linearise({x.s, x.hull.lo, x.hull.hi, 0.0, end, leads, KeyMode::Both, 1e-9});
    return x;
}

TEST(Smoothing, CurveStaysInTheRawChannelMonotoneWithZeroCurvatureAtJoints) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const WigglyLayer x = wigglySetup(seed);
        ASSERT_GT(x.lines.vertices.size(), 4u);
        for (EpsilonRule rule : {EpsilonRule::Exact, EpsilonRule::Paper}) {
            for (CornerForm form : {CornerForm::GraphLimit, CornerForm::Euclidean}) {
                const SmoothedPath path =
                    smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                                  {rule, form, 0.0, 40, 64, CornerProfile::Bezier});
                const PathSamples samples = evaluateSmoothedPath(path, x.s);
                for (std::size_t i = 0; i < x.s.size(); ++i) {
                    ASSERT_GE(samples.theta[i], x.rawLo[i] - 1e-12) << i;
                    ASSERT_LE(samples.theta[i], x.rawHi[i] + 1e-12) << i;
                    ASSERT_GE(samples.dTheta[i], -1e-12) << i;
                }
                // Flat, straight layer ends (intermediate layer).
                EXPECT_NEAR(samples.dTheta.front(), 0.0, 1e-12);
                EXPECT_NEAR(samples.ddTheta.front(), 0.0, 1e-9);
                EXPECT_NEAR(samples.dTheta.back(), 0.0, 1e-12);
                EXPECT_NEAR(samples.ddTheta.back(), 0.0, 1e-9);
                double previousEnd = -1.0;
                for (const SmoothedCorner& c : path.corners) {
                    ASSERT_NE(c.limitedBy, CornerLimit::None);
                    EXPECT_GE(c.curve.sBegin(), previousEnd - 1e-12); // disjoint spans
                    previousEnd = c.curve.sEnd();
                    const std::vector<double> joints{c.curve.sBegin(), c.s, c.curve.sEnd()};
                    const PathSamples at = evaluateSmoothedPath(path, joints);
                    for (double dd : at.ddTheta) {
                        EXPECT_NEAR(dd, 0.0, 1e-9);
                    }
                }
            }
        }
    }
}

TEST(Smoothing, ExactEpsilonIsNeverSmallerThanThePaperRule) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const WigglyLayer x = wigglySetup(seed);
        const SmoothedPath exact = smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                                                 {EpsilonRule::Exact, CornerForm::Euclidean});
        const SmoothedPath paper = smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                                                 {EpsilonRule::Paper, CornerForm::Euclidean});
        ASSERT_EQ(exact.corners.size(), paper.corners.size());
        for (std::size_t k = 0; k < exact.corners.size(); ++k) {
            // The paper's epsilon0 is sufficient (W1), so the bisection finds at least as much.
            EXPECT_GE(std::abs(exact.corners[k].epsilon),
                      std::abs(paper.corners[k].epsilon) * (1.0 - 1e-9));
        }
        EXPECT_LE(peakSecondDerivative(exact), peakSecondDerivative(paper) * (1.0 + 1e-9));
    }
}

TEST(Smoothing, FinalClearanceIsKept) {
    const WigglyLayer x = wigglySetup(3);
    const double clearance = 0.02;
    for (CornerProfile profile : {CornerProfile::Bezier, CornerProfile::Plateau}) {
        const SmoothedPath path =
            smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                          {EpsilonRule::Exact, CornerForm::GraphLimit, clearance, 40, 64, profile});
        const PathSamples samples = evaluateSmoothedPath(path, x.s);
        for (std::size_t i = 0; i < x.s.size(); ++i) {
            EXPECT_GE(std::min(samples.theta[i] - x.rawLo[i], x.rawHi[i] - samples.theta[i]),
                      clearance - 1e-9);
        }
    }
}

// [X] Plateau corners (CornerProfile::Plateau): the same guarantees as the Bezier pair with a
// flatter theta''.
TEST(Smoothing, PlateauCurveStaysInTheRawChannelMonotoneAndG2) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const WigglyLayer x = wigglySetup(seed);
        for (EpsilonRule rule : {EpsilonRule::Exact, EpsilonRule::Paper}) {
            SmoothingSettings settings{rule, CornerForm::GraphLimit};
            settings.profile = CornerProfile::Plateau;
            const SmoothedPath path =
                smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi, settings);
            const PathSamples samples = evaluateSmoothedPath(path, x.s);
            for (std::size_t i = 0; i < x.s.size(); ++i) {
                EXPECT_GE(samples.theta[i], x.rawLo[i] - 1e-9) << "seed " << seed << " i " << i;
                EXPECT_LE(samples.theta[i], x.rawHi[i] + 1e-9) << "seed " << seed << " i " << i;
                EXPECT_GE(samples.dTheta[i], -1e-12);
                if (i > 0) {
                    EXPECT_GE(samples.theta[i], samples.theta[i - 1] - 1e-12);
                }
            }
            double previousEnd = -1e300;
            for (const SmoothedCorner& c : path.corners) {
                ASSERT_EQ(c.profile, CornerProfile::Plateau);
                if (c.limitedBy == CornerLimit::None) {
                    continue;
                }
                EXPECT_GE(c.sBegin(), previousEnd - 1e-12); // disjoint spans
                previousEnd = c.sEnd();
                // G2 at the span ends: on the polyline, with its slope and theta'' = 0.
                for (double end : {c.sBegin(), c.sEnd()}) {
                    const GraphPoint at = c.plateau.at(end);
                    const double slope = end < c.s ? c.plateau.k1 : c.plateau.k2;
                    EXPECT_NEAR(at.value, c.plateau.p2.y() + slope * (end - c.s), 1e-12);
                    EXPECT_NEAR(at.first, slope, 1e-12);
                    EXPECT_NEAR(at.second, 0.0, 1e-12);
                }
            }
        }
    }
}

TEST(Smoothing, PlateauPeakIsBelowTheBezierPeakOnTheSamePolyline) {
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const WigglyLayer x = wigglySetup(seed);
        SmoothingSettings plateau{EpsilonRule::Exact, CornerForm::GraphLimit};
        plateau.profile = CornerProfile::Plateau;
        const double plateauPeak =
            peakSecondDerivative(smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi, plateau));
        SmoothingSettings bezier{EpsilonRule::Exact, CornerForm::GraphLimit};
        bezier.profile = CornerProfile::Bezier;
        const double bezierPeak =
            peakSecondDerivative(smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi, bezier));
        EXPECT_LT(plateauPeak, bezierPeak) << "seed " << seed;
    }
}

// The exact rule finds the largest feasible half-width: a channel-limited corner 1e-6 wider
// leaves the channel at some sample.
TEST(Smoothing, PlateauExactRuleIsTheLargestFeasibleHalfWidth) {
    const WigglyLayer x = wigglySetup(4);
    SmoothingSettings settings{EpsilonRule::Exact, CornerForm::GraphLimit};
    settings.profile = CornerProfile::Plateau;
    const SmoothedPath path = smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi, settings);
    int channelLimited = 0;
    for (const SmoothedCorner& c : path.corners) {
        if (c.limitedBy != CornerLimit::Channel) {
            continue;
        }
        ++channelLimited;
        PlateauCorner wider = c.plateau;
        wider.halfWidth *= 1.0 + 1e-6;
        double worst = 0.0;
        for (std::size_t i = 0; i < x.s.size(); ++i) {
            const double value = wider.at(x.s[i]).value;
            worst = std::max({worst, x.rawLo[i] - value, value - x.rawHi[i]});
        }
        EXPECT_GT(worst, 0.0) << "corner at S = " << c.s;
    }
    EXPECT_GT(channelLimited, 0);
}

} // namespace
} // namespace bladeaxis::scheduling

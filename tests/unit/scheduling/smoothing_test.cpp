// Spec §10.1 row "smoothing" (§5.4, §5.8): both epsilon rules and both corner forms.
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
                const SmoothedPath path = smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                                                        {rule, form, 0.0, 40, 64});
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
    const SmoothedPath path =
        smoothCorners(x.lines.vertices, x.s, x.rawLo, x.rawHi,
                      {EpsilonRule::Exact, CornerForm::GraphLimit, clearance, 40, 64});
    const PathSamples samples = evaluateSmoothedPath(path, x.s);
    for (std::size_t i = 0; i < x.s.size(); ++i) {
        EXPECT_GE(std::min(samples.theta[i] - x.rawLo[i], x.rawHi[i] - samples.theta[i]),
                  clearance - 1e-9);
    }
}

} // namespace
} // namespace bladeaxis::scheduling

// The §9 baseline: the interior point's QP and LP against the closed forms of §9.4, optimality
// checked by feasible perturbations (the problem is convex: no feasible direction may lower the
// objective), and against the engine, whose schedule is feasible for the same problem and so can
// never beat it.

#include "core/blade/presets.h"
#include "core/optimal/layer_optimum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace bladeaxis::optimal {
namespace {

constexpr double kEndSlack = 1e-3;
constexpr int kFamilyBlades = 10;          // with the demo: about 2 s
constexpr std::size_t kSpecSamples = 2001; // spec §10.1: n = 2000

// An intermediate layer of length L from 0 to thetaEnd with a channel wide enough not to bind.
LayerBounds wideLayer(double length, double thetaEnd, std::size_t samples) {
    LayerBounds b;
    for (std::size_t i = 0; i < samples; ++i) {
        b.s.push_back(length * static_cast<double>(i) / static_cast<double>(samples - 1));
        b.lower.push_back(-10.0);
        b.upper.push_back(10.0);
    }
    b.start = 0.0;
    b.end = thetaEnd;
    return b;
}

TEST(OptimalLayer, SmoothestIsTheCubicOracle) {
    const double length = 40.0, thetaEnd = 1.0;
    const LayerBounds bounds = wideLayer(length, thetaEnd, 161);
    auto qp = smoothestLayer(bounds);
    ASSERT_TRUE(qp.has_value()) << qp.error().toString();
    const double oracle = 12.0 * thetaEnd * thetaEnd / std::pow(length, 3);
    EXPECT_NEAR(qp->secondDifferenceEnergy, oracle, 0.05 * oracle);
    for (std::size_t i = 0; i < bounds.s.size(); i += 20) {
        const double u = bounds.s[i] / length;
        EXPECT_NEAR(qp->theta[i], thetaEnd * (3 * u * u - 2 * u * u * u), 0.02) << i;
    }
}

TEST(OptimalLayer, MinimumPeakIsTheBangBangOracle) {
    const double length = 40.0, thetaEnd = 1.0;
    auto lp = minimumPeakLayer(wideLayer(length, thetaEnd, 161));
    ASSERT_TRUE(lp.has_value()) << lp.error().toString();
    // Discretely the zero end slopes take one step at each end: the oracle 4 theta_e / S_e^2
    // on the length between them, to within the grid.
    const double inner = length - 2.0 * length / 160.0;
    const double oracle = 4.0 * thetaEnd / (inner * inner);
    EXPECT_NEAR(lp->peakSecondDifference, oracle, 0.02 * oracle);
}

// Spec §10.1 asks for the §9.4 analytic optima within 1 % at n = 2000 and a KKT residual below
// 1e-6. (The ADMM of spec §9.3 did not converge at n = 2001 within 50000 iterations: the
// Hessian's condition grows like n^4. The interior point takes 20-40 Newton steps.)
TEST(OptimalLayer, MinimumPeakIsTheBangBangOracleWithinOnePercentOnTwoThousandSamples) {
    const double length = 200.0, thetaEnd = 6.0;
    auto lp = minimumPeakLayer(wideLayer(length, thetaEnd, kSpecSamples));
    ASSERT_TRUE(lp.has_value()) << lp.error().toString();
    const double peak = 4.0 * thetaEnd / (length * length);
    EXPECT_NEAR(lp->peakSecondDifference, peak, 0.01 * peak);
}

TEST(OptimalLayer, SmoothestIsTheCubicOracleWithinOnePercentWithResidualsBelowOneMillionth) {
    const double length = 200.0, thetaEnd = 6.0;
    auto qp = smoothestLayer(wideLayer(length, thetaEnd, kSpecSamples));
    ASSERT_TRUE(qp.has_value()) << qp.error().toString();
    const double energy = 12.0 * thetaEnd * thetaEnd / std::pow(length, 3);
    EXPECT_NEAR(qp->secondDifferenceEnergy, energy, 0.01 * energy);
    EXPECT_LT(qp->relativeResidual, 1e-6);
}

std::vector<scheduling::LayerResult> scheduledLayers(const blade::BladeSpec& bladeSpec,
                                                     const blade::HelicalPathSpec& pathSpec) {
    auto bladeModel = blade::Blade::create(bladeSpec);
    auto path = blade::generateHelicalPath(*bladeModel, pathSpec);
    scheduling::ScheduleInput input;
    input.toolRadius = pathSpec.toolRadius;
    input.centres = path->centre;
    for (const auto& record : path->path.records) {
        input.axes.push_back(record.axis);
    }
    return scheduling::schedule(input, scheduling::bestPreset())->layers;
}

struct DemoLayers {
    std::vector<scheduling::LayerResult> layers =
        scheduledLayers(blade::demoBladeSpec(), blade::demoPathSpec());
};

const DemoLayers& demo() {
    static const DemoLayers d;
    return d;
}

// Spec §9.4: the engine's schedule is feasible for the optimum's problem (the same raw channel,
// monotone, the same end values and slopes; checked below), so neither of its objectives can be
// below the optimum's. The slack covers the solver's tolerance (a relative KKT residual of 1e-9,
// 1e-6 where it stalls) and the flat end step of §9.1, which the engine meets analytically: where a
// corner reaches into the first or last interval its first difference is up to ~1e-5 rad (turbine
// layers), not 0. Over the demo, a symmetric blade and the family the engine stays >= 1.2x the
// optimum in both objectives, so 0.1 % slack is far from hiding a violation.
struct Dominance {
    std::size_t layers = 0, mirroredEnds = 0;
};

Dominance expectTheEngineNeverBeatsTheOptimum(const std::vector<scheduling::LayerResult>& layers,
                                              const std::string& label, double slack) {
    Dominance seen;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        auto qp = smoothestLayer(bounds);
        EXPECT_TRUE(qp.has_value()) << label << " layer " << k << ": " << qp.error().toString();
        auto lp = minimumPeakLayer(bounds);
        EXPECT_TRUE(lp.has_value()) << label << " layer " << k << ": " << lp.error().toString();
        if (!qp || !lp) {
            continue;
        }
        // Like for like: the engine's schedule is a feasible point of the optimum's problem.
        for (std::size_t i = 0; i < bounds.s.size(); ++i) {
            EXPECT_GE(layers[k].theta[i], bounds.lower[i] - 1e-9) << label << " " << k << " " << i;
            EXPECT_LE(layers[k].theta[i], bounds.upper[i] + 1e-9) << label << " " << k << " " << i;
        }
        const double enginePeak = peakSecondDifference(bounds, layers[k].theta);
        const double engineEnergy = secondDifferenceEnergy(bounds, layers[k].theta);
        EXPECT_GE(enginePeak, (1.0 - slack) * lp->peakSecondDifference) << label << " " << k;
        EXPECT_GE(engineEnergy, (1.0 - slack) * qp->secondDifferenceEnergy) << label << " " << k;
        // Up to the solver's feasibility tolerance: at a pinched end the QP may touch the bound
        // ~1e-6 rad outside, which the mirrored sample's D2 (2 / h^2 per rad) shows in the peak.
        EXPECT_LE(lp->peakSecondDifference, qp->peakSecondDifference * (1.0 + 1e-3) + 1e-9)
            << "the min-peak optimum has the lowest peak, " << label << " layer " << k;
        for (std::size_t i = 0; i < bounds.s.size(); ++i) {
            EXPECT_GE(qp->theta[i], bounds.lower[i] - 1e-6) << label << " " << k << " " << i;
            EXPECT_LE(qp->theta[i], bounds.upper[i] + 1e-6) << label << " " << k << " " << i;
            if (i > 0) {
                EXPECT_GE(qp->theta[i] - qp->theta[i - 1], -1e-6) << label << " " << k << " " << i;
            }
        }
        seen.mirroredEnds += (bounds.mirroredStart ? 1 : 0) + (bounds.mirroredEnd ? 1 : 0);
        ++seen.layers;
    }
    return seen;
}

TEST(OptimalLayer, TheEngineNeverBeatsTheOptimumOnTheDemoBlade) {
    const Dominance seen = expectTheEngineNeverBeatsTheOptimum(demo().layers, "demo", kEndSlack);
    EXPECT_EQ(seen.layers, demo().layers.size());
}

// Issue 4: a section without a concave run has fallback base points. The hull rises up to them,
// and the optimum used to be missing on every such layer because the junction sat at the hull's
// top at the base point, where no flat last step fits. The engine's junction now leaves room for
// its shortest lead-out, so the spec's flat step fits and no end needs the mirrored form.
TEST(OptimalLayer, EveryLayerOfASymmetricBladeHasBothOptima) {
    blade::BladeSpec symmetric = blade::demoBladeSpec();
    symmetric.profile = blade::NacaProfile{0.0, 0.4, 0.12};
    blade::HelicalPathSpec path = blade::demoPathSpec();
    path.revolutions = 4;
    const auto layers = scheduledLayers(symmetric, path);
    ASSERT_GE(layers.size(), 3u);
    const Dominance seen = expectTheEngineNeverBeatsTheOptimum(layers, "symmetric", kEndSlack);
    EXPECT_EQ(seen.layers, layers.size());
    EXPECT_EQ(seen.mirroredEnds, 0u) << "a junction without room for a flat end step";
}

// Where a junction value does lie outside the hull at the neighbouring sample (a pinched base
// point, §4.6), the zero end slope takes the mirrored form and both optima still exist.
TEST(OptimalLayer, APinchedEndIsMirroredAndBothOptimaExist) {
    scheduling::LayerResult layer;
    const std::size_t n = 41;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = static_cast<double>(i);
        layer.s.push_back(s);
        layer.lo.push_back(0.02 * s - 0.4);
        layer.hi.push_back(0.02 * s + 0.1); // rising up to the end: HI(n-2) < HI(n-1)
    }
    layer.theta.assign(n, 0.0);
    layer.theta.back() = layer.hi.back(); // the junction at the hull's top at the base point
    const LayerBounds bounds = boundsOf(layer, false, false);
    ASSERT_TRUE(bounds.mirroredEnd);
    ASSERT_FALSE(bounds.mirroredStart);
    for (const Objective objective : {Objective::SmoothestQp, Objective::MinimumPeakLp}) {
        auto optimum =
            objective == Objective::SmoothestQp ? smoothestLayer(bounds) : minimumPeakLayer(bounds);
        ASSERT_TRUE(optimum.has_value()) << optimum.error().toString();
        EXPECT_NEAR(optimum->theta.front(), 0.0, 1e-6);
        EXPECT_NEAR(optimum->theta.back(), bounds.end, 1e-6);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_GE(optimum->theta[i], bounds.lower[i] - 1e-6) << i;
            EXPECT_LE(optimum->theta[i], bounds.upper[i] + 1e-6) << i;
        }
    }
}

TEST(OptimalLayer, TheEngineNeverBeatsTheOptimumOnTheSyntheticFamily) {
    auto family = blade::syntheticFamily(2022, kFamilyBlades);
    ASSERT_TRUE(family.has_value()) << family.error().toString();
    std::size_t mirroredEnds = 0;
    for (const blade::FamilyMember& member : *family) {
        const auto layers = scheduledLayers(member.blade, member.path);
        const Dominance seen = expectTheEngineNeverBeatsTheOptimum(layers, member.name, kEndSlack);
        EXPECT_EQ(seen.layers, layers.size()) << member.name;
        mirroredEnds += seen.mirroredEnds;
    }
    std::printf("[ measure  ] %zu family layer ends needed the mirrored form\n", mirroredEnds);
}

// The min-peak LP exists on every layer of the reproduction's 36 blades (docs/results.md). On
// three of them the interior point's iterates used to stall at round-off near a degenerate
// optimum and the layer had no optimum; the best iterate is now taken when it met 100x the
// tolerance, and it still never beats the engine's schedule, which is feasible for the LP.
TEST(OptimalLayer, EveryLayerOfTheReproductionFamilyHasTheMinimumPeakOptimum) {
    auto family = blade::syntheticFamily(2022, 36);
    ASSERT_TRUE(family.has_value()) << family.error().toString();
    std::size_t layersSolved = 0;
    for (const blade::FamilyMember& member : *family) {
        const auto layers = scheduledLayers(member.blade, member.path);
        for (std::size_t k = 0; k < layers.size(); ++k) {
            const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
            auto lp = minimumPeakLayer(bounds);
            ASSERT_TRUE(lp.has_value())
                << member.name << " layer " << k << ": " << lp.error().toString();
            EXPECT_GE(peakSecondDifference(bounds, layers[k].theta),
                      (1.0 - kEndSlack) * lp->peakSecondDifference)
                << member.name << " layer " << k;
            ++layersSolved;
        }
    }
    EXPECT_GT(layersSolved, 36u * 3u);
}

// Convexity: a step from the optimum towards any feasible point (here the engine's schedule)
// cannot lower the objective. An independent check of optimality, not of the solver's residuals.
TEST(OptimalLayer, NoFeasibleStepLowersTheOptimum) {
    const auto& layers = demo().layers;
    for (std::size_t k = 1; k + 1 < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], false, false);
        auto qp = smoothestLayer(bounds);
        ASSERT_TRUE(qp.has_value());
        for (double step : {1e-3, 1e-2, 0.1}) {
            std::vector<double> mixed(qp->theta.size());
            for (std::size_t i = 0; i < mixed.size(); ++i) {
                mixed[i] = (1.0 - step) * qp->theta[i] + step * layers[k].theta[i];
            }
            EXPECT_GE(secondDifferenceEnergy(bounds.s, mixed),
                      qp->secondDifferenceEnergy * (1.0 - 1e-4))
                << "layer " << k << " step " << step;
        }
    }
}

TEST(OptimalLayer, BadBoundsAreErrors) {
    LayerBounds b = wideLayer(10.0, 1.0, 10);
    b.lower[3] = 20.0; // above the upper bound
    EXPECT_FALSE(smoothestLayer(b).has_value());
    EXPECT_FALSE(smoothestLayer(wideLayer(10.0, 1.0, 3)).has_value());
    LayerBounds nan = wideLayer(10.0, 1.0, 10);
    nan.s[4] = std::nan("");
    EXPECT_FALSE(smoothestLayer(nan).has_value());
    EXPECT_FALSE(smoothestLayer(LayerBounds{}).has_value());
    EXPECT_FALSE(minimumPeakLayer(LayerBounds{}).has_value());
    EXPECT_FALSE(minimumPeakLayer(b).has_value());
    EXPECT_FALSE(minimumPeakLayer(nan).has_value());
    LayerBounds nanBound = wideLayer(10.0, 1.0, 10);
    nanBound.upper[5] = std::nan("");
    EXPECT_FALSE(smoothestLayer(nanBound).has_value());
    EXPECT_FALSE(minimumPeakLayer(nanBound).has_value());
}

} // namespace
} // namespace bladeaxis::optimal

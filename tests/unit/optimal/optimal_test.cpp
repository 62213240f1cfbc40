// The §9 baseline: the ADMM QP against the closed form of §9.4, optimality checked by feasible
// perturbations (the problem is convex: no feasible direction may lower the objective), and
// against the engine, whose schedule is feasible for the same problem and so can never beat it.

#include "core/blade/presets.h"
#include "core/optimal/layer_optimum.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::optimal {
namespace {

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

struct DemoLayers {
    std::vector<scheduling::LayerResult> layers;
    DemoLayers() {
        auto bladeModel = blade::Blade::create(blade::demoBladeSpec());
        auto path = blade::generateHelicalPath(*bladeModel, blade::demoPathSpec());
        scheduling::ScheduleInput input;
        input.toolRadius = blade::demoPathSpec().toolRadius;
        input.centres = path->centre;
        for (const auto& record : path->path.records) {
            input.axes.push_back(record.axis);
        }
        layers = scheduling::schedule(input, scheduling::bestPreset())->layers;
    }
};

const DemoLayers& demo() {
    static const DemoLayers d;
    return d;
}

TEST(OptimalLayer, TheEngineNeverBeatsTheOptimumOnTheDemoBlade) {
    const auto& layers = demo().layers;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        auto qp = smoothestLayer(bounds);
        ASSERT_TRUE(qp.has_value()) << k << ": " << qp.error().toString();
        auto lp = minimumPeakLayer(bounds);
        ASSERT_TRUE(lp.has_value()) << k << ": " << lp.error().toString();
        EXPECT_GE(peakSecondDifference(layers[k].s, layers[k].theta),
                  0.99 * lp->peakSecondDifference)
            << "layer " << k;
        EXPECT_LE(lp->peakSecondDifference, qp->peakSecondDifference * (1.0 + 1e-6))
            << "the min-peak optimum has the lowest peak, layer " << k;
        const double engineEnergy = secondDifferenceEnergy(layers[k].s, layers[k].theta);
        // The engine's end slope is zero analytically, not in the first difference: 1 % slack.
        EXPECT_GE(engineEnergy, 0.99 * qp->secondDifferenceEnergy) << "layer " << k;
        for (std::size_t i = 0; i < bounds.s.size(); ++i) {
            ASSERT_GE(qp->theta[i], bounds.lower[i] - 1e-6) << k << " " << i;
            ASSERT_LE(qp->theta[i], bounds.upper[i] + 1e-6) << k << " " << i;
            if (i > 0) {
                ASSERT_GE(qp->theta[i] - qp->theta[i - 1], -1e-6) << k << " " << i;
            }
        }
    }
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

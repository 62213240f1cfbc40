// The optimum on programs of a real size: a finishing pass of 40 revolutions at 1.5 um chordal
// tolerance has 26,000-93,000 samples and layers of 660-1,870 samples with chords from 1 nm to
// 1 mm. Every layer must have both optima, feasible, and never beaten by the engine's schedule.

#include "core/blade/presets.h"
#include "core/optimal/layer_optimum.h"
#include "core/scheduling/schedule.h"
#include "tests/support/real_size_pass.h"

#include <gtest/gtest.h>

#include <string>

namespace bladeaxis::optimal {
namespace {

std::vector<scheduling::LayerResult> realSizeLayers(const blade::BladeSpec& bladeSpec,
                                                    int revolutions) {
    auto schedule = test::scheduleRealSizePass(bladeSpec, revolutions);
    EXPECT_TRUE(schedule.has_value()) << schedule.error().toString();
    return schedule ? schedule->layers : std::vector<scheduling::LayerResult>{};
}

void expectFeasible(const LayerBounds& bounds, const std::vector<double>& theta,
                    const std::string& label) {
    ASSERT_EQ(theta.size(), bounds.s.size()) << label;
    for (std::size_t i = 0; i < theta.size(); ++i) {
        EXPECT_GE(theta[i], bounds.lower[i] - 1e-6) << label << " sample " << i;
        EXPECT_LE(theta[i], bounds.upper[i] + 1e-6) << label << " sample " << i;
        if (i > 0) {
            EXPECT_GE(theta[i] - theta[i - 1], -1e-6) << label << " sample " << i;
        }
    }
}

TEST(OptimalRealSize, EveryLayerOfAFortyRevolutionFinishingPassHasBothOptima) {
    blade::BladeSpec weak = blade::demoBladeSpec();
    weak.profile = blade::NacaProfile{0.04, 0.40, 0.18}; // the 34,641-sample program
    const auto layers = realSizeLayers(weak, 40);
    ASSERT_GE(layers.size(), 40U);
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        const std::string label = "layer " + std::to_string(k);
        auto qp = smoothestLayer(bounds);
        auto lp = minimumPeakLayer(bounds);
        ASSERT_TRUE(qp.has_value()) << label << ": " << qp.error().toString();
        ASSERT_TRUE(lp.has_value()) << label << ": " << lp.error().toString();
        EXPECT_LT(qp->relativeResidual, 1e-6) << label;
        EXPECT_LT(lp->relativeResidual, 1e-6) << label;
        expectFeasible(bounds, qp->theta, label + " qp");
        expectFeasible(bounds, lp->theta, label + " lp");
        // The engine's schedule is feasible for the same problem (spec §9.4).
        EXPECT_GE(peakSecondDifference(bounds, layers[k].theta),
                  (1.0 - 1e-3) * lp->peakSecondDifference)
            << label;
        EXPECT_GE(secondDifferenceEnergy(bounds, layers[k].theta),
                  (1.0 - 1e-3) * qp->secondDifferenceEnergy)
            << label;
    }
}

// A turbine profile's sharp trailing edge puts samples 1 nm apart in every layer: the layer is
// solved without them (optimalLayer) and they are interpolated inside their bounds.
TEST(OptimalRealSize, LayersWithNanometreChordsHaveBothOptima) {
    blade::BladeSpec turbine = blade::demoBladeSpec();
    turbine.profile = blade::TurbineProfile{};
    const auto layers = realSizeLayers(turbine, 6);
    ASSERT_GE(layers.size(), 6U);
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const LayerBounds bounds = boundsOf(layers[k], k == 0, k + 1 == layers.size());
        for (const Objective objective : {Objective::SmoothestQp, Objective::MinimumPeakLp}) {
            const std::string label = "layer " + std::to_string(k) +
                                      (objective == Objective::SmoothestQp ? " qp" : " lp");
            auto theta = optimalLayer(bounds, objective);
            ASSERT_TRUE(theta.has_value()) << label << ": " << theta.error().toString();
            expectFeasible(bounds, *theta, label);
        }
    }
}

} // namespace
} // namespace bladeaxis::optimal

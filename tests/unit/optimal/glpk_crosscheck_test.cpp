// optimal-lp against a second independent solver packaged in Debian: GLPK's primal simplex
// (libglpk-dev), on small random layers of the §9.1 problem. Exact vertex arithmetic of a
// simplex is the reference our interior point must reach. (The QP is checked against ALGLIB's
// dense IPM in alglib_crosscheck_test.cpp; GLPK has no QP.)

#include "core/optimal/layer_optimum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glpk.h>
#include <random>
#include <vector>

namespace bladeaxis::optimal {
namespace {

LayerBounds randomWindingLayer(std::mt19937& random, int samples) {
    std::uniform_real_distribution<double> step(0.2, 1.5), width(0.1, 0.6), wobble(-0.05, 0.05);
    LayerBounds b;
    double s = 0.0;
    for (int i = 0; i < samples; ++i) {
        b.s.push_back(s);
        const double centre = 2.0 * s / (1.0 * samples) + wobble(random);
        b.lower.push_back(centre - width(random));
        b.upper.push_back(centre + width(random));
        s += step(random);
    }
    // Zero end slopes put the junction value at two samples: inside both channels.
    b.start = std::max(b.lower[0], b.lower[1]);
    b.end = std::min(b.upper[b.upper.size() - 2], b.upper.back());
    return b;
}

// GLPK problem builder: columns 1..n are theta, column n+1 is the peak t; rows as in §9.1.
class GlpkLp {
  public:
    explicit GlpkLp(int columns) : m_lp(glp_create_prob()) {
        glp_set_obj_dir(m_lp, GLP_MIN);
        glp_add_cols(m_lp, columns);
    }
    ~GlpkLp() { glp_delete_prob(m_lp); }
    GlpkLp(const GlpkLp&) = delete;
    GlpkLp& operator=(const GlpkLp&) = delete;

    glp_prob* get() { return m_lp; }

    // One row sum(value * x[col]) within [lo, hi]; kind is GLP_FX, GLP_LO, GLP_UP.
    void addRow(const std::vector<std::pair<int, double>>& entries, int kind, double lo,
                double hi) {
        const int row = glp_add_rows(m_lp, 1);
        glp_set_row_bnds(m_lp, row, kind, lo, hi);
        std::vector<int> index{0};
        std::vector<double> value{0.0}; // GLPK arrays are 1-based
        for (const auto& [col, v] : entries) {
            index.push_back(col);
            value.push_back(v);
        }
        glp_set_mat_row(m_lp, row, static_cast<int>(entries.size()), index.data(), value.data());
    }

  private:
    glp_prob* m_lp;
};

double glpkMinimumPeak(const LayerBounds& b) {
    const int n = static_cast<int>(b.s.size());
    GlpkLp lp(n + 1);
    for (int i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        glp_set_col_bnds(lp.get(), i + 1, GLP_DB, b.lower[k], b.upper[k]);
    }
    glp_set_col_bnds(lp.get(), n + 1, GLP_LO, 0.0, 0.0);
    glp_set_obj_coef(lp.get(), n + 1, 1.0);
    for (int i = 1; i < n; ++i) {
        lp.addRow({{i, -1.0}, {i + 1, 1.0}}, GLP_LO, 0.0, 0.0); // monotone
    }
    lp.addRow({{1, 1.0}}, GLP_FX, b.start, b.start);
    lp.addRow({{1, -1.0}, {2, 1.0}}, GLP_FX, 0.0, 0.0); // zero start slope
    lp.addRow({{n, 1.0}}, GLP_FX, b.end, b.end);
    lp.addRow({{n - 1, -1.0}, {n, 1.0}}, GLP_FX, 0.0, 0.0); // zero end slope
    for (std::size_t i = 1; i + 1 < b.s.size(); ++i) {
        const double before = b.s[i] - b.s[i - 1], after = b.s[i + 1] - b.s[i];
        const double c = 2.0 / (before + after);
        const int col = static_cast<int>(i) + 1;
        const std::vector<std::pair<int, double>> d2{
            {col - 1, c / before}, {col, -c * (1.0 / before + 1.0 / after)}, {col + 1, c / after}};
        auto up = d2, down = d2;
        up.emplace_back(n + 1, -1.0);
        down.emplace_back(n + 1, 1.0);
        lp.addRow(up, GLP_UP, 0.0, 0.0);   // D2 theta - t <= 0
        lp.addRow(down, GLP_LO, 0.0, 0.0); // D2 theta + t >= 0
    }
    glp_smcp parameters;
    glp_init_smcp(&parameters);
    parameters.msg_lev = GLP_MSG_OFF;
    parameters.presolve = GLP_ON;
    EXPECT_EQ(glp_simplex(lp.get(), &parameters), 0);
    EXPECT_EQ(glp_get_status(lp.get()), GLP_OPT);
    return glp_get_obj_val(lp.get());
}

TEST(OptimalGlpkCrossCheck, MinimumPeakEqualsGlpksSimplexOptimum) {
    std::mt19937 random(2022);
    for (int instance = 0; instance < 8; ++instance) {
        const LayerBounds b = randomWindingLayer(random, 12 + 4 * instance);
        auto ours = minimumPeakLayer(b);
        ASSERT_TRUE(ours.has_value()) << ours.error().toString();
        const double reference = glpkMinimumPeak(b);
        EXPECT_GT(reference, 0.0) << instance;
        EXPECT_NEAR(ours->peakSecondDifference, reference, 1e-6 * reference + 1e-9) << instance;
    }
}

TEST(OptimalGlpkCrossCheck, SmoothestNeverHasALowerPeakThanGlpksOptimum) {
    // An LP bound on the QP: no feasible schedule, the smoothest included, has a peak below the
    // min-peak optimum, and the smoothest one stays feasible (the bound is what GLPK certifies).
    std::mt19937 random(7);
    for (int instance = 0; instance < 5; ++instance) {
        const LayerBounds b = randomWindingLayer(random, 20);
        auto qp = smoothestLayer(b);
        ASSERT_TRUE(qp.has_value()) << qp.error().toString();
        EXPECT_GE(qp->peakSecondDifference, glpkMinimumPeak(b) * (1.0 - 1e-6)) << instance;
    }
}

} // namespace
} // namespace bladeaxis::optimal

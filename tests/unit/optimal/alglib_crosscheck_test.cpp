// Our solvers against an independent one packaged in Debian (ALGLIB 3.19: minqp's dense IPM
// and minlp's dual simplex), on small random layers of the §9.1 problem.

#include "core/optimal/layer_optimum.h"

#include <gtest/gtest.h>

#include <libalglib/optimization.h>
#include <random>

namespace bladeaxis::optimal {
namespace {

LayerBounds randomLayer(std::mt19937& random) {
    std::uniform_real_distribution<double> step(0.3, 1.2), width(0.15, 0.5);
    LayerBounds b;
    double s = 0.0;
    for (int i = 0; i < 25; ++i) {
        b.s.push_back(s);
        const double centre = 1.5 * s / 20.0; // a rising channel the schedule must follow
        b.lower.push_back(centre - width(random));
        b.upper.push_back(centre + width(random));
        s += step(random);
    }
    b.start = std::clamp(0.0, b.lower.front(), b.upper.front());
    b.end = std::clamp(1.5 * b.s.back() / 20.0, b.lower.back(), b.upper.back());
    return b;
}

// The D2 row of sample i over `columns` variables.
std::vector<double> secondDifferenceRow(const LayerBounds& b, std::size_t i, std::size_t columns) {
    std::vector<double> row(columns, 0.0);
    const double before = b.s[i] - b.s[i - 1], after = b.s[i + 1] - b.s[i];
    const double c = 2.0 / (before + after);
    row[i - 1] = c / before;
    row[i] = -c * (1.0 / before + 1.0 / after);
    row[i + 1] = c / after;
    return row;
}

// The constraint rows shared by both problems: monotone, junction values, zero end slopes.
struct Rows {
    std::vector<std::vector<double>> a;
    std::vector<double> lower, upper;
    void add(std::vector<double> row, double lo, double hi) {
        a.push_back(std::move(row));
        lower.push_back(lo);
        upper.push_back(hi);
    }
    void load(alglib::real_2d_array& matrix, alglib::real_1d_array& al,
              alglib::real_1d_array& au) const {
        const auto k = static_cast<alglib::ae_int_t>(a.size());
        const auto n = static_cast<alglib::ae_int_t>(a.front().size());
        matrix.setlength(k, n);
        al.setlength(k);
        au.setlength(k);
        for (alglib::ae_int_t r = 0; r < k; ++r) {
            for (alglib::ae_int_t c = 0; c < n; ++c) {
                matrix[r][c] = a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
            }
            al[r] = lower[static_cast<std::size_t>(r)];
            au[r] = upper[static_cast<std::size_t>(r)];
        }
    }
};

Rows scheduleRows(const LayerBounds& b, std::size_t columns) {
    const std::size_t n = b.s.size();
    Rows rows;
    auto row = [&](std::initializer_list<std::pair<std::size_t, double>> entries) {
        std::vector<double> r(columns, 0.0);
        for (const auto& [col, value] : entries) {
            r[col] = value;
        }
        return r;
    };
    for (std::size_t i = 0; i + 1 < n; ++i) {
        rows.add(row({{i, -1.0}, {i + 1, 1.0}}), 0.0, alglib::fp_posinf);
    }
    rows.add(row({{0, 1.0}}), b.start, b.start);
    rows.add(row({{0, -1.0}, {1, 1.0}}), 0.0, 0.0);
    rows.add(row({{n - 1, 1.0}}), b.end, b.end);
    rows.add(row({{n - 2, -1.0}, {n - 1, 1.0}}), 0.0, 0.0);
    return rows;
}

double alglibMinimumPeak(const LayerBounds& b) {
    const std::size_t n = b.s.size();
    Rows rows = scheduleRows(b, n + 1);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        std::vector<double> up = secondDifferenceRow(b, i, n + 1), down = up;
        up[n] = -1.0;
        down[n] = 1.0;
        rows.add(up, alglib::fp_neginf, 0.0);   // D2 theta - t <= 0
        rows.add(down, 0.0, alglib::fp_posinf); // D2 theta + t >= 0
    }
    alglib::real_1d_array cost, lower, upper, x;
    cost.setlength(static_cast<alglib::ae_int_t>(n + 1));
    lower.setlength(static_cast<alglib::ae_int_t>(n + 1));
    upper.setlength(static_cast<alglib::ae_int_t>(n + 1));
    for (std::size_t i = 0; i < n; ++i) {
        cost[static_cast<alglib::ae_int_t>(i)] = 0.0;
        lower[static_cast<alglib::ae_int_t>(i)] = b.lower[i];
        upper[static_cast<alglib::ae_int_t>(i)] = b.upper[i];
    }
    cost[static_cast<alglib::ae_int_t>(n)] = 1.0;
    lower[static_cast<alglib::ae_int_t>(n)] = 0.0;
    upper[static_cast<alglib::ae_int_t>(n)] = alglib::fp_posinf;
    alglib::real_2d_array a;
    alglib::real_1d_array al, au;
    rows.load(a, al, au);
    alglib::minlpstate state;
    alglib::minlpreport report;
    alglib::minlpcreate(static_cast<alglib::ae_int_t>(n + 1), state);
    alglib::minlpsetcost(state, cost);
    alglib::minlpsetbc(state, lower, upper);
    alglib::minlpsetlc2dense(state, a, al, au);
    alglib::minlpsetalgodss(state, 0.0);
    alglib::minlpoptimize(state);
    alglib::minlpresults(state, x, report);
    EXPECT_GT(report.terminationtype, 0);
    return x[static_cast<alglib::ae_int_t>(n)];
}

double alglibSmoothestEnergy(const LayerBounds& b) {
    const std::size_t n = b.s.size();
    alglib::real_2d_array hessian;
    hessian.setlength(static_cast<alglib::ae_int_t>(n), static_cast<alglib::ae_int_t>(n));
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t c = 0; c < n; ++c) {
            hessian[static_cast<alglib::ae_int_t>(r)][static_cast<alglib::ae_int_t>(c)] = 0.0;
        }
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const auto row = secondDifferenceRow(b, i, n);
        const double weight = 0.5 * (b.s[i + 1] - b.s[i - 1]);
        for (std::size_t r = i - 1; r <= i + 1; ++r) {
            for (std::size_t c = i - 1; c <= i + 1; ++c) {
                // 1/2 x'Hx = sum w (D2 x)^2
                hessian[static_cast<alglib::ae_int_t>(r)][static_cast<alglib::ae_int_t>(c)] +=
                    2.0 * weight * row[r] * row[c];
            }
        }
    }
    alglib::real_1d_array linear, lower, upper, x;
    linear.setlength(static_cast<alglib::ae_int_t>(n));
    lower.setlength(static_cast<alglib::ae_int_t>(n));
    upper.setlength(static_cast<alglib::ae_int_t>(n));
    for (std::size_t i = 0; i < n; ++i) {
        linear[static_cast<alglib::ae_int_t>(i)] = 0.0;
        lower[static_cast<alglib::ae_int_t>(i)] = b.lower[i];
        upper[static_cast<alglib::ae_int_t>(i)] = b.upper[i];
    }
    alglib::real_2d_array a;
    alglib::real_1d_array al, au;
    scheduleRows(b, n).load(a, al, au);
    alglib::minqpstate state;
    alglib::minqpreport report;
    alglib::minqpcreate(static_cast<alglib::ae_int_t>(n), state);
    alglib::minqpsetquadraticterm(state, hessian);
    alglib::minqpsetlinearterm(state, linear);
    alglib::minqpsetbc(state, lower, upper);
    alglib::minqpsetlc2dense(state, a, al, au);
    alglib::minqpsetalgodenseipm(state, 1e-12);
    alglib::minqpoptimize(state);
    alglib::minqpresults(state, x, report);
    EXPECT_GT(report.terminationtype, 0);
    std::vector<double> theta(n);
    for (std::size_t i = 0; i < n; ++i) {
        theta[i] = x[static_cast<alglib::ae_int_t>(i)];
    }
    return secondDifferenceEnergy(b.s, theta);
}

TEST(OptimalCrossCheck, MinimumPeakAgreesWithAlglibsSimplex) {
    std::mt19937 random(11);
    for (int instance = 0; instance < 6; ++instance) {
        const LayerBounds b = randomLayer(random);
        auto ours = minimumPeakLayer(b);
        ASSERT_TRUE(ours.has_value()) << ours.error().toString();
        const double reference = alglibMinimumPeak(b);
        EXPECT_NEAR(ours->peakSecondDifference, reference, 1e-6 * reference + 1e-9) << instance;
    }
}

TEST(OptimalCrossCheck, SmoothestAgreesWithAlglibsInteriorPoint) {
    std::mt19937 random(12);
    for (int instance = 0; instance < 6; ++instance) {
        const LayerBounds b = randomLayer(random);
        auto ours = smoothestLayer(b);
        ASSERT_TRUE(ours.has_value()) << ours.error().toString();
        const double reference = alglibSmoothestEnergy(b);
        EXPECT_NEAR(ours->secondDifferenceEnergy, reference, 1e-4 * reference + 1e-12) << instance;
    }
}

} // namespace
} // namespace bladeaxis::optimal

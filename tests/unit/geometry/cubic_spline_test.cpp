#include "core/geometry/cubic_spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

namespace bladeaxis::geometry {
namespace {

struct Cubic {
    double c0, c1, c2, c3;
    double value(double x) const { return c0 + x * (c1 + x * (c2 + x * c3)); }
    double first(double x) const { return c1 + x * (2 * c2 + 3 * c3 * x); }
    double second(double x) const { return 2 * c2 + 6 * c3 * x; }
    double third() const { return 6 * c3; }
};

std::vector<double> randomKnots(std::mt19937& rng, int count) {
    std::uniform_real_distribution<double> gap(0.05, 2.0);
    std::vector<double> knots{-1.5};
    for (int i = 1; i < count; ++i) {
        knots.push_back(knots.back() + gap(rng));
    }
    return knots;
}

std::vector<double> sample(const Cubic& f, const std::vector<double>& knots) {
    std::vector<double> values;
    for (double x : knots) {
        values.push_back(f.value(x));
    }
    return values;
}

// Checks value and all derivatives at the knots and at interior points of every interval.
void expectReproduces(const Cubic& f, const std::vector<double>& knots, double tol) {
    const std::vector<double> values = sample(f, knots);
    const CubicSpline spline(knots, values);
    ASSERT_TRUE(spline.isValid());
    ASSERT_EQ(spline.size(), knots.size());
    for (std::size_t i = 0; i < knots.size(); ++i) {
        EXPECT_NEAR(spline.firstDerivativeAtKnot(i), f.first(knots[i]), tol) << i;
        EXPECT_NEAR(spline.secondDerivativeAtKnot(i), f.second(knots[i]), tol) << i;
        EXPECT_NEAR(spline.thirdDerivativeAtKnot(i), f.third(), tol) << i;
    }
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
        for (double t : {0.0, 0.13, 0.5, 0.91, 1.0}) {
            const double x = knots[i] + t * (knots[i + 1] - knots[i]);
            EXPECT_NEAR(spline.value(i, x), f.value(x), tol) << i << " " << t;
            EXPECT_NEAR(spline.firstDerivative(i, x), f.first(x), tol) << i << " " << t;
            EXPECT_NEAR(spline.secondDerivative(i, x), f.second(x), tol) << i << " " << t;
        }
        EXPECT_NEAR(spline.thirdDerivative(i), f.third(), tol) << i;
    }
}

TEST(CubicSpline, NotAKnotReproducesCubicsOnRandomNonUniformKnots) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
    for (int count : {4, 5, 6, 10, 57}) {
        for (int trial = 0; trial < 10; ++trial) {
            const Cubic f{coefficient(rng), coefficient(rng), coefficient(rng), coefficient(rng)};
            const std::vector<double> knots = randomKnots(rng, count);
            // Values grow like x^3 (|x| up to ~100): scale the tolerance with the magnitudes.
            const double scale = std::pow(std::max(1.0, std::abs(knots.back())), 3.0);
            expectReproduces(f, knots, 1e-10 * scale);
        }
    }
}

TEST(CubicSpline, TwoKnotsGiveTheLine) {
    const std::vector<double> knots{1.0, 3.0};
    const std::vector<double> values{2.0, -2.0};
    const CubicSpline spline(knots, values);
    ASSERT_TRUE(spline.isValid());
    EXPECT_DOUBLE_EQ(spline.value(0, 2.0), 0.0);
    EXPECT_DOUBLE_EQ(spline.firstDerivativeAtKnot(0), -2.0);
    EXPECT_DOUBLE_EQ(spline.firstDerivativeAtKnot(1), -2.0);
    EXPECT_EQ(spline.secondDerivativeAtKnot(1), 0.0);
    EXPECT_EQ(spline.thirdDerivativeAtKnot(0), 0.0);
}

TEST(CubicSpline, ThreeKnotsGiveTheParabola) {
    const Cubic parabola{1.0, -0.5, 0.75, 0.0};
    expectReproduces(parabola, {-1.0, 0.2, 3.0}, 1e-12);
}

TEST(CubicSpline, IsTwiceContinuousAndNotAKnotOnRandomData) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    const std::vector<double> knots = randomKnots(rng, 30);
    std::vector<double> values;
    for (std::size_t i = 0; i < knots.size(); ++i) {
        values.push_back(value(rng));
    }
    const CubicSpline spline(knots, values);
    ASSERT_TRUE(spline.isValid());
    for (std::size_t i = 1; i + 1 < knots.size(); ++i) {
        const double x = knots[i];
        EXPECT_NEAR(spline.value(i - 1, x), values[i], 1e-12);
        EXPECT_NEAR(spline.value(i, x), values[i], 1e-12);
        EXPECT_NEAR(spline.firstDerivative(i - 1, x), spline.firstDerivative(i, x), 1e-9);
        EXPECT_NEAR(spline.secondDerivative(i - 1, x), spline.secondDerivative(i, x), 1e-9);
    }
    const std::size_t last = knots.size() - 2;
    EXPECT_NEAR(spline.thirdDerivative(0), spline.thirdDerivative(1), 1e-8);
    EXPECT_NEAR(spline.thirdDerivative(last), spline.thirdDerivative(last - 1), 1e-8);
}

TEST(CubicSpline, RejectsInvalidKnotsAndValues) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> four{1.0, 2.0, 3.0, 4.0};
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0, 1.0, 1.0, 2.0}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0, 2.0, 1.0, 3.0}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0, nan, 1.0, 3.0}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0, 1.0, 2.0, inf}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{-inf, 1.0, 2.0, 3.0}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0, 1.0, 2.0}, four).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{0.0}, std::vector<double>{1.0}).isValid());
    EXPECT_FALSE(CubicSpline(std::vector<double>{}, std::vector<double>{}).isValid());
    EXPECT_FALSE(CubicSpline(four, std::vector<double>{1.0, nan, 2.0, 3.0}).isValid());
    EXPECT_FALSE(CubicSpline(four, std::vector<double>{1.0, 2.0, 3.0, nan}).isValid());
    EXPECT_FALSE(CubicSpline(four, std::vector<double>{1.0, 2.0, 3.0, inf}).isValid());
    EXPECT_TRUE(CubicSpline(four, four).isValid());
}

TEST(NotAKnotMoments, SharedKnotsGiveEachSeriesTheMomentsOfItsOwnSpline) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> value(-5.0, 5.0);
    for (int count : {2, 3, 4, 5, 9, 100}) {
        const std::vector<double> knots = randomKnots(rng, count);
        std::vector<std::vector<double>> values(3);
        for (std::vector<double>& series : values) {
            for (int i = 0; i < count; ++i) {
                series.push_back(value(rng));
            }
        }
        std::vector<std::vector<double>> moments(values.size(), std::vector<double>(knots.size()));
        const std::vector<std::span<const double>> valueSpans(values.begin(), values.end());
        const std::vector<std::span<double>> momentSpans(moments.begin(), moments.end());
        notAKnotMoments(knots, valueSpans, momentSpans);
        for (std::size_t k = 0; k < values.size(); ++k) {
            const CubicSpline own(knots, values[k]);
            ASSERT_TRUE(own.isValid());
            for (std::size_t i = 0; i < knots.size(); ++i) {
                EXPECT_EQ(moments[k][i], own.secondDerivativeAtKnot(i)) << count << " " << k;
            }
        }
    }
}

// One elimination of the knots' system serves any number of series solved one after another:
// the not-a-knot spline through a cubic is that cubic, so each series' moments are its second
// derivatives at the knots.
TEST(NotAKnotSystem, OneEliminationSolvesEverySeriesExactlyForCubics) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
    for (int count : {4, 6, 250}) {
        const std::vector<double> knots = randomKnots(rng, count);
        const NotAKnotSystem system(knots);
        for (int series = 0; series < 3; ++series) {
            const double c1 = coefficient(rng), c2 = coefficient(rng), c3 = coefficient(rng);
            std::vector<double> values;
            for (double x : knots) {
                values.push_back(1.0 + c1 * x + c2 * x * x + c3 * x * x * x);
            }
            std::vector<double> moments(knots.size(), std::nan(""));
            system.solve(values, moments);
            for (std::size_t i = 0; i < knots.size(); ++i) {
                const double exact = 2.0 * c2 + 6.0 * c3 * knots[i];
                EXPECT_NEAR(moments[i], exact, 1e-7 * (1.0 + std::abs(exact))) << count << " " << i;
            }
        }
    }
}

TEST(CubicSplineInterval, FirstDerivativeBoundHoldsAcrossTheInterval) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int trial = 0; trial < 2000; ++trial) {
        const double scale = std::ldexp(1.0, exponent(rng) / 2);
        CubicSplineInterval piece;
        piece.left = unit(rng) * scale;
        piece.right = piece.left + (1.5 + unit(rng)) * scale;
        piece.leftValue = unit(rng) * std::ldexp(1.0, exponent(rng));
        piece.rightValue = unit(rng) * std::ldexp(1.0, exponent(rng));
        piece.leftMoment = unit(rng) * std::ldexp(1.0, exponent(rng));
        piece.rightMoment = trial % 3 == 0 ? -piece.leftMoment : unit(rng) * scale;
        const double bound = piece.firstDerivativeBound();
        for (int k = 0; k <= 50; ++k) {
            const double x = k == 50 ? piece.right : piece.left + 0.02 * k * piece.width();
            EXPECT_LE(std::abs(piece.firstDerivative(x)), bound) << trial << " " << k;
        }
    }
}

} // namespace
} // namespace bladeaxis::geometry

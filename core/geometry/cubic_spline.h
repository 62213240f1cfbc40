#pragma once
// Interpolating C2 cubic spline with not-a-knot end conditions (spec §8.1), used to take
// axis derivatives along the path parameter. O(n) set-up (tridiagonal solve), O(1) evaluation
// when the interval is known.

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace bladeaxis::geometry {

// One interval [left, right] of a cubic spline, given by its end values and moments (second
// derivatives). The evaluation formulas of CubicSpline live here, inline, so that a caller
// evaluating several points of one interval lets the compiler share the terms they have in
// common, and so that splines stored elsewhere (several axes over one knot vector) evaluate
// exactly as CubicSpline does.
struct CubicSplineInterval {
    double left = 0.0, right = 0.0;
    double leftValue = 0.0, rightValue = 0.0;
    double leftMoment = 0.0, rightMoment = 0.0;

    double width() const { return right - left; }

    double value(double x) const {
        const double h = width();
        const double a = right - x;
        const double b = x - left;
        return leftMoment * a * a * a / (6.0 * h) + rightMoment * b * b * b / (6.0 * h) +
               (leftValue / h - leftMoment * h / 6.0) * a +
               (rightValue / h - rightMoment * h / 6.0) * b;
    }

    double firstDerivative(double x) const {
        const double h = width();
        const double a = right - x;
        const double b = x - left;
        return -leftMoment * a * a / (2.0 * h) + rightMoment * b * b / (2.0 * h) +
               (rightValue - leftValue) / h - (rightMoment - leftMoment) * h / 6.0;
    }

    // An upper bound of |firstDerivative(x)| for left <= x <= right, rounding included, so that
    // a caller looking for the peak can pass over intervals that cannot raise it. The first two
    // terms of q' have |M| a^2 / 2h <= |M| h / 2 (a and b lie in [0, h], also as rounded); the
    // sum of the magnitudes of the four terms is then exceeded by a few ulps at most, which the
    // relative margin covers many times over, and the absolute one covers subnormal terms.
    double firstDerivativeBound() const {
        const double h = width();
        const double terms = (std::abs(leftMoment) + std::abs(rightMoment)) * h / 2.0 +
                             std::abs((rightValue - leftValue) / h) +
                             std::abs((rightMoment - leftMoment) * h / 6.0);
        return terms * (1.0 + 1e-9) + std::numeric_limits<double>::min();
    }

    double secondDerivative(double x) const {
        return (leftMoment * (right - x) + rightMoment * (x - left)) / width();
    }

    double thirdDerivative() const { return (rightMoment - leftMoment) / width(); }
};

// The not-a-knot spline system over a knot vector (strictly increasing and finite, at least 2),
// eliminated once: the tridiagonal matrix depends only on the knots, so the moments of any
// number of value series over them are then substituted one series at a time, and a caller
// need hold only the series it is working on. Keeps a view of the knots and one pivot per knot.
class NotAKnotSystem {
  public:
    explicit NotAKnotSystem(std::span<const double> knots);

    // The moments (second derivatives at the knots) of the spline through `values`; both have
    // the size of the knots. The same as a CubicSpline of its own gives.
    void solve(std::span<const double> values, std::span<double> moments) const;

  private:
    std::span<const double> m_knots;
    std::vector<double> m_pivots; // of the interior rows, when there are at least 4 knots
};

// Moments of the not-a-knot splines through several value series over the same knots
// (NotAKnotSystem, eliminated once); values[k] and moments[k] have the size of knots.
void notAKnotMoments(std::span<const double> knots, std::span<const std::span<const double>> values,
                     std::span<const std::span<double>> moments);

class CubicSpline {
  public:
    // Knots must be strictly increasing and at least 2; with 2 or 3 knots the spline is the
    // interpolating line or parabola. Throws nothing; call isValid() on doubtful input.
    CubicSpline(std::span<const double> knots, std::span<const double> values);

    bool isValid() const { return m_valid; }
    std::size_t size() const { return m_knots.size(); }

    // The interval starting at knot i (i + 1 < size()).
    CubicSplineInterval interval(std::size_t i) const {
        return {m_knots[i],      m_knots[i + 1], m_values[i],
                m_values[i + 1], m_second[i],    m_second[i + 1]};
    }

    // Value and derivatives on interval i (knots[i] <= x <= knots[i + 1]).
    double value(std::size_t i, double x) const { return interval(i).value(x); }
    double firstDerivative(std::size_t i, double x) const { return interval(i).firstDerivative(x); }
    double secondDerivative(std::size_t i, double x) const {
        return interval(i).secondDerivative(x);
    }
    double thirdDerivative(std::size_t i) const { return interval(i).thirdDerivative(); }

    // Derivatives at knot i (taken from the interval starting at i, the last from the left).
    double firstDerivativeAtKnot(std::size_t i) const {
        return firstDerivative(intervalAtKnot(i), m_knots[i]);
    }
    double secondDerivativeAtKnot(std::size_t i) const { return m_second[i]; }
    double thirdDerivativeAtKnot(std::size_t i) const { return thirdDerivative(intervalAtKnot(i)); }

  private:
    std::size_t intervalAtKnot(std::size_t i) const { return i + 1 < m_knots.size() ? i : i - 1; }

    std::vector<double> m_knots;
    std::vector<double> m_values;
    std::vector<double> m_second; // second derivative at each knot (moments)
    bool m_valid = false;
};

} // namespace bladeaxis::geometry

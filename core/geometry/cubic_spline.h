#pragma once
// Interpolating C2 cubic spline with not-a-knot end conditions (spec §8.1), used to take
// axis derivatives along the path parameter. O(n) set-up (tridiagonal solve), O(1) evaluation
// when the interval is known.

#include <span>
#include <vector>

namespace bladeaxis::geometry {

class CubicSpline {
  public:
    // Knots must be strictly increasing and at least 2; with 2 or 3 knots the spline is the
    // interpolating line or parabola. Throws nothing; call isValid() on doubtful input.
    CubicSpline(std::span<const double> knots, std::span<const double> values);

    bool isValid() const { return m_valid; }
    std::size_t size() const { return m_knots.size(); }

    // Value and derivatives on interval `interval` (knots[interval] <= x <= knots[interval+1]).
    double value(std::size_t interval, double x) const;
    double firstDerivative(std::size_t interval, double x) const;
    double secondDerivative(std::size_t interval, double x) const;
    double thirdDerivative(std::size_t interval) const;

    // Derivatives at knot i (taken from the interval starting at i, the last from the left).
    double firstDerivativeAtKnot(std::size_t i) const;
    double secondDerivativeAtKnot(std::size_t i) const;
    double thirdDerivativeAtKnot(std::size_t i) const;

  private:
    std::vector<double> m_knots;
    std::vector<double> m_values;
    std::vector<double> m_second; // second derivative at each knot (moments)
    bool m_valid = false;
};

} // namespace bladeaxis::geometry

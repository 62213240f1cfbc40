#include "core/geometry/cubic_spline.h"

#include <cmath>

namespace bladeaxis::geometry {

namespace {

// The tridiagonal system of the not-a-knot spline through n >= 4 knots, in the interior moments
// M_1 .. M_{n-2}: row r is the continuity of q' at knot r + 1. M_0 and M_{n-1} are substituted
// from the not-a-knot conditions at knots 1 and n-2, which changes the first and the last row.
// The coefficients depend only on the knots and are computed as the rows are eliminated.
class NotAKnotRows {
  public:
    explicit NotAKnotRows(std::span<const double> knots) : m_knots(knots) {
        const std::size_t last = rows() - 1;
        const double h0 = h(0), h1 = h(1);
        // Not-a-knot at knot 1: M_0 = ((h0 + h1) M_1 - h0 M_2) / h1, substituted into row 0.
        m_firstDiag = 2.0 * (h0 + h1) + h0 * (h0 + h1) / h1;
        m_firstSuper = h1 - h0 * h0 / h1;
        // Not-a-knot at knot n-2: M_{n-1} = ((hl + hp) M_{n-2} - hl M_{n-3}) / hp.
        const double hl = h(last + 1), hp = h(last);
        m_lastDiag = 2.0 * (hp + hl) + hl * (hl + hp) / hp;
        m_lastSub = hp - hl * hl / hp;
    }

    std::size_t rows() const { return m_knots.size() - 2; }
    double h(std::size_t i) const { return m_knots[i + 1] - m_knots[i]; }

    double sub(std::size_t row) const { return row + 1 == rows() ? m_lastSub : h(row); }
    double diag(std::size_t row) const {
        if (row == 0) {
            return m_firstDiag;
        }
        return row + 1 == rows() ? m_lastDiag : 2.0 * (h(row) + h(row + 1));
    }
    double super(std::size_t row) const { return row == 0 ? m_firstSuper : h(row + 1); }

    // The moments at the two end knots from the not-a-knot conditions.
    double firstMoment(std::span<const double> moments) const {
        return ((h(0) + h(1)) * moments[1] - h(0) * moments[2]) / h(1);
    }
    double lastMoment(std::span<const double> moments) const {
        const std::size_t n = m_knots.size();
        const double hl = h(n - 2), hp = h(n - 3);
        return ((hl + hp) * moments[n - 2] - hl * moments[n - 3]) / hp;
    }

  private:
    std::span<const double> m_knots;
    double m_firstDiag = 0.0, m_firstSuper = 0.0, m_lastDiag = 0.0, m_lastSub = 0.0;
};

double slope(std::span<const double> values, const NotAKnotRows& system, std::size_t i) {
    return (values[i + 1] - values[i]) / system.h(i);
}

} // namespace

// Thomas algorithm on the rows: the pivots depend only on the knots and are eliminated here;
// solve() substitutes a right-hand side.
NotAKnotSystem::NotAKnotSystem(std::span<const double> knots) : m_knots(knots) {
    if (knots.size() < 4) {
        return;
    }
    const NotAKnotRows system(knots);
    const std::size_t rows = system.rows();
    m_pivots.resize(rows);
    m_pivots[0] = system.diag(0);
    for (std::size_t row = 1; row < rows; ++row) {
        const double factor = system.sub(row) / m_pivots[row - 1];
        m_pivots[row] = system.diag(row) - factor * system.super(row - 1);
    }
}

// The right-hand side 6 (slope_{r+1} - slope_r) of row r is eliminated into moments[r + 1] and
// substituted back there. The factors are divided again rather than kept: a division that no
// substitution waits for costs less than 8 bytes per knot.
void NotAKnotSystem::solve(std::span<const double> values, std::span<double> moments) const {
    const std::size_t n = m_knots.size();
    if (n == 2) {
        moments[0] = moments[1] = 0.0;
        return;
    }
    if (n == 3) {
        // The not-a-knot spline through three points is their parabola: constant moment.
        const double d0 = (values[1] - values[0]) / (m_knots[1] - m_knots[0]);
        const double d1 = (values[2] - values[1]) / (m_knots[2] - m_knots[1]);
        moments[0] = moments[1] = moments[2] = 2.0 * (d1 - d0) / (m_knots[2] - m_knots[0]);
        return;
    }
    const NotAKnotRows system(m_knots);
    const std::size_t rows = system.rows();
    double previousSlope = slope(values, system, 1);
    moments[1] = 6.0 * (previousSlope - slope(values, system, 0));
    for (std::size_t row = 1; row < rows; ++row) {
        const double factor = system.sub(row) / m_pivots[row - 1];
        const double next = slope(values, system, row + 1);
        moments[row + 1] = 6.0 * (next - previousSlope) - factor * moments[row];
        previousSlope = next;
    }
    moments[rows] = moments[rows] / m_pivots[rows - 1];
    for (std::size_t row = rows - 1; row-- > 0;) {
        moments[row + 1] =
            (moments[row + 1] - system.super(row) * moments[row + 2]) / m_pivots[row];
    }
    moments[0] = system.firstMoment(moments);
    moments[n - 1] = system.lastMoment(moments);
}

void notAKnotMoments(std::span<const double> knots, std::span<const std::span<const double>> values,
                     std::span<const std::span<double>> moments) {
    const NotAKnotSystem system(knots);
    for (std::size_t k = 0; k < values.size(); ++k) {
        system.solve(values[k], moments[k]);
    }
}

CubicSpline::CubicSpline(std::span<const double> knots, std::span<const double> values)
    : m_knots(knots.begin(), knots.end()), m_values(values.begin(), values.end()) {
    const std::size_t n = m_knots.size();
    if (n < 2 || n != m_values.size()) {
        return;
    }
    // Every knot and value must be finite (the last ones included: an infinite end knot passes
    // the ordering test and a NaN last value would spread through the whole solve).
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(m_knots[i]) || !std::isfinite(m_values[i])) {
            return;
        }
        if (i + 1 < n && !(m_knots[i + 1] > m_knots[i])) {
            return;
        }
    }
    m_second.resize(n);
    const std::span<const double> series[] = {m_values};
    const std::span<double> moments[] = {m_second};
    notAKnotMoments(m_knots, series, moments);
    m_valid = true;
}

} // namespace bladeaxis::geometry

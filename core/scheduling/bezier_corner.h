#pragma once
// Spec §5.1-5.3, §5.6: the corrected paired-cubic Bezier corner (double inner control points),
// in the Euclidean form (angles in the rad/mm plane) and in the unit-free graph-limit form, and
// the analytic evaluation of theta(S), theta'(S), theta''(S) on it.

#include "core/geometry/vec.h"

#include <array>
#include <cmath>

namespace bladeaxis::scheduling {

struct CubicBezier {
    // (S, theta) control points; zero until set (a corner left unsmoothed has no curve)
    std::array<Vec2, 4> control{Vec2::Zero(), Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};

    Vec2 point(double t) const;
    Vec2 firstDerivative(double t) const;  // dB/dt
    Vec2 secondDerivative(double t) const; // d2B/dt2
};

struct BezierPair {
    CubicBezier first;  // B_i0, B_i1, B_i1, B_i3
    CubicBezier second; // B_i3, B_j1, B_j1, B_j3

    double sBegin() const { return first.control[0].x(); }
    double sEnd() const { return second.control[3].x(); }
};

// Corrected Eq. 9 (errata E5-E8): corner P2 between directions alpha (in) and beta (out), both
// in [0, pi/2); epsilon = signed vertical offset of the joint, with the sign of beta - alpha.
BezierPair euclideanCornerPair(const Vec2& p2, double alpha, double beta, double epsilon);

// Graph-limit form [X] with slopes k1, k2: h = 2 epsilon / (k2 - k1), span [S2 - 2h, S2 + 2h].
BezierPair graphLimitCornerPair(const Vec2& p2, double k1, double k2, double epsilon);

// Corrected Eq. 12 (E9-E11): the largest |epsilon| with d1 <= f1 l1 and d2 <= f2 l2, where
// l1, l2 are the Euclidean lengths of the incoming and outgoing segments.
double euclideanEpsilonLimit(double alpha, double beta, double l1, double l2, double f1, double f2);
// Graph-limit version: 2h <= f1 dS1 and 2h <= f2 dS2 (dS = horizontal segment lengths).
double graphLimitEpsilonLimit(double k1, double k2, double dS1, double dS2, double f1, double f2);

struct GraphPoint {
    double value = 0.0;  // theta
    double first = 0.0;  // dtheta/dS
    double second = 0.0; // d2theta/dS2
};

// One coordinate of a cubic in power form: c0 + t (c1 + t (c2 + t c3)).
struct PowerCubic {
    double c0, c1, c2, c3;

    PowerCubic(double p0, double p1, double p2, double p3)
        : c0(p0), c1(3.0 * (p1 - p0)), c2(3.0 * (p2 - 2.0 * p1 + p0)),
          c3(p3 - p0 + 3.0 * (p1 - p2)) {}
    double value(double t) const { return c0 + t * (c1 + t * (c2 + t * c3)); }
    double first(double t) const { return c1 + t * (2.0 * c2 + 3.0 * t * c3); }
    double second(double t) const { return 2.0 * c2 + 6.0 * t * c3; }
};

// A cubic as the graph theta(S), for walking samples in increasing S (spec §5.8): the power
// forms are built once per cubic, and each sample's parameter starts from the previous one's.
class CubicGraph {
  public:
    explicit CubicGraph(const CubicBezier& cubic);
    // theta, theta', theta'' at abscissa s (clamped to the curve), starting from `parameter` if
    // it lies in (0, 1); `parameter` becomes the parameter found.
    GraphPoint at(double s, double& parameter) const;

  private:
    PowerCubic m_x, m_y;
    double m_x3;
};

// theta and its S-derivatives at abscissa s (clamped to the curve), t found by Halley steps on
// the strictly increasing x(t) (spec §5.8).
GraphPoint evaluateCubic(const CubicBezier& cubic, double s);
// The same starting from a parameter guess in (0, 1) (outside: none), which is replaced by the
// parameter found: walking the samples of one cubic in order, each starts from the previous.
GraphPoint evaluateCubic(const CubicBezier& cubic, double s, double& parameter);
GraphPoint evaluatePair(const BezierPair& pair, double s);
// theta'' at a parameter value, from the analytic derivatives: (x'y'' - y'x'') / x'^3.
double secondDerivativeAt(const CubicBezier& cubic, double t);

// [X] Plateau corner (graph form, unit-free like §5.2's graph limit): on S in [S2 - W, S2 + W],
// theta''(S) = A (1 - v^4) with v = (S - S2) / W and A = (k2 - k1) / (1.6 W), so the slope turns
// from k1 to k2 and theta'' is 0 at both ends (G2, as the Bezier pair). theta is the polyline
// plus the deviation (A W^2) P(|v|), P(u) = u^2/2 - u^6/30 - 4u/5 + 1/3: even in v, monotone on
// each side, largest at S2 where it is |epsilon| = |k2 - k1| W / 4.8, and proportional to W at
// a fixed v (homothety, so feasibility is monotone in W as in §5.3). Its peak |theta''| is
// 1.25 x the least possible for the slope change over the span (the Bezier pair's is 8/3 x).
struct PlateauCorner {
    Vec2 p2 = Vec2::Zero(); // the polyline vertex (S2, theta2)
    double k1 = 0.0;        // incoming slope, rad/mm
    double k2 = 0.0;        // outgoing slope, rad/mm
    double halfWidth = 0.0; // W, mm (> 0)

    double sBegin() const { return p2.x() - halfWidth; }
    double sEnd() const { return p2.x() + halfWidth; }
    // |theta''| at S2, the largest along the corner.
    double peak() const { return std::abs(k2 - k1) / (1.6 * halfWidth); }
    // Signed vertical offset of the curve from P2 at S2.
    double epsilon() const { return (k2 - k1) * halfWidth / 4.8; }
    // theta, theta', theta'' at s (clamped to the span).
    GraphPoint at(double s) const;
};

// The deviation profile P(u) of the plateau corner for u = |S - S2| / W in [0, 1] (0 beyond).
double plateauDeviation(double u);
// dP/du, <= 0 on [0, 1] (0 beyond).
double plateauDeviationSlope(double u);
// The half-width W of the plateau corner whose deviation at S2 is |epsilon|.
double plateauHalfWidth(double k1, double k2, double epsilon);

} // namespace bladeaxis::scheduling

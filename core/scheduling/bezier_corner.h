#pragma once
// Spec §5.1-5.3, §5.6: the corrected paired-cubic Bezier corner (double inner control points),
// in the Euclidean form (angles in the rad/mm plane) and in the unit-free graph-limit form, and
// the analytic evaluation of theta(S), theta'(S), theta''(S) on it.

#include "core/geometry/vec.h"

#include <array>

namespace bladeaxis::scheduling {

struct CubicBezier {
    std::array<Vec2, 4> control; // (S, theta) control points

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

} // namespace bladeaxis::scheduling

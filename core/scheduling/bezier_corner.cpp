#include "core/scheduling/bezier_corner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bladeaxis::scheduling {

Vec2 CubicBezier::point(double t) const {
    const double u = 1.0 - t;
    return u * u * u * control[0] + 3.0 * u * u * t * control[1] + 3.0 * u * t * t * control[2] +
           t * t * t * control[3];
}

Vec2 CubicBezier::firstDerivative(double t) const {
    const double u = 1.0 - t;
    return 3.0 * u * u * (control[1] - control[0]) + 6.0 * u * t * (control[2] - control[1]) +
           3.0 * t * t * (control[3] - control[2]);
}

Vec2 CubicBezier::secondDerivative(double t) const {
    return 6.0 * (1.0 - t) * (control[2] - 2.0 * control[1] + control[0]) +
           6.0 * t * (control[3] - 2.0 * control[2] + control[1]);
}

namespace {

Vec2 unit(double angle) {
    return {std::cos(angle), std::sin(angle)};
}

BezierPair pairFrom(const Vec2& bi0, const Vec2& bi1, const Vec2& bi3, const Vec2& bj1,
                    const Vec2& bj3) {
    return {CubicBezier{{bi0, bi1, bi1, bi3}}, CubicBezier{{bi3, bj1, bj1, bj3}}};
}

} // namespace

BezierPair euclideanCornerPair(const Vec2& p2, double alpha, double beta, double epsilon) {
    const double gamma = 0.5 * (alpha + beta);
    const double delta = 0.5 * (beta - alpha);
    const double scale = epsilon / std::sin(delta); // > 0: epsilon has the sign of delta
    const Vec2 bi0 = p2 - scale * (std::cos(alpha) + std::cos(gamma)) * unit(alpha);
    const Vec2 bi1 = p2 - scale * std::cos(gamma) * unit(alpha);
    const Vec2 bi3 = p2 + Vec2(0.0, epsilon);
    const Vec2 bj1 = p2 + scale * std::cos(gamma) * unit(beta);
    const Vec2 bj3 = p2 + scale * (std::cos(beta) + std::cos(gamma)) * unit(beta);
    return pairFrom(bi0, bi1, bi3, bj1, bj3);
}

BezierPair graphLimitCornerPair(const Vec2& p2, double k1, double k2, double epsilon) {
    const double h = 2.0 * epsilon / (k2 - k1);
    const Vec2 bi0 = p2 + Vec2(-2.0 * h, -2.0 * h * k1);
    const Vec2 bi1 = p2 + Vec2(-h, -h * k1);
    const Vec2 bi3 = p2 + Vec2(0.0, epsilon);
    const Vec2 bj1 = p2 + Vec2(h, h * k2);
    const Vec2 bj3 = p2 + Vec2(2.0 * h, 2.0 * h * k2);
    return pairFrom(bi0, bi1, bi3, bj1, bj3);
}

double euclideanEpsilonLimit(double alpha, double beta, double l1, double l2, double f1,
                             double f2) {
    const double gamma = 0.5 * (alpha + beta);
    const double sinDelta = std::abs(std::sin(0.5 * (beta - alpha)));
    return std::min(f1 * l1 * sinDelta / (std::cos(alpha) + std::cos(gamma)),
                    f2 * l2 * sinDelta / (std::cos(beta) + std::cos(gamma)));
}

double graphLimitEpsilonLimit(double k1, double k2, double dS1, double dS2, double f1, double f2) {
    const double h = 0.5 * std::min(f1 * dS1, f2 * dS2);
    return 0.5 * h * std::abs(k2 - k1);
}

double secondDerivativeAt(const CubicBezier& cubic, double t) {
    const Vec2 d1 = cubic.firstDerivative(t);
    const Vec2 d2 = cubic.secondDerivative(t);
    return (d1.x() * d2.y() - d1.y() * d2.x()) / (d1.x() * d1.x() * d1.x());
}

namespace {

// Parameter t with x(t) = s on a cubic whose x is strictly increasing (spec §5.8). Halley steps
// on the cubic x(t), safeguarded by a bisection bracket: a few steps reach the round-off level
// that the 50-60 plain bisection steps of §5.8 reach, which matters because every CL sample
// inside a corner span is evaluated this way.
double parameterAt(const PowerCubic& x, double x3, double s, double t) {
    // A residual at the round-off level of evaluating x(t) cannot be reduced further.
    const double converged =
        8.0 * std::numeric_limits<double>::epsilon() * (std::abs(x.c0) + std::abs(x3 - x.c0));
    double low = 0.0;
    double high = 1.0;
    for (int step = 0; step < 100; ++step) {
        const double f = x.value(t) - s;
        if (std::abs(f) <= converged) {
            return t;
        }
        (f < 0.0 ? low : high) = t;
        // Halley step (cubic convergence): consecutive samples start within ~1e-2 of the root,
        // so two steps reach round-off.
        const double slope = x.first(t);
        const double denominator = 2.0 * slope * slope - f * x.second(t);
        double next = slope > 0.0 && denominator > 0.0 ? t - 2.0 * f * slope / denominator
                                                       : 0.5 * (low + high);
        // On these cubics x' >= 1.5 h, |x''| <= 6 h and |x'''| = 12 h in the graph limit (the
        // Euclidean form is similar), so after a step below 1e-6 the error is below 1e-17: no
        // further evaluation is needed.
        if (std::abs(next - t) <= 1e-6 && next >= low && next <= high) {
            return next;
        }
        if (!(next > low && next < high)) {
            next = 0.5 * (low + high);
        }
        if (high - low <= 4.0 * std::numeric_limits<double>::epsilon()) {
            return next;
        }
        t = next;
    }
    return t;
}

} // namespace

CubicGraph::CubicGraph(const CubicBezier& cubic)
    : m_x(cubic.control[0].x(), cubic.control[1].x(), cubic.control[2].x(), cubic.control[3].x()),
      m_y(cubic.control[0].y(), cubic.control[1].y(), cubic.control[2].y(), cubic.control[3].y()),
      m_x3(cubic.control[3].x()) {}

GraphPoint CubicGraph::at(double s, double& parameter) const {
    double t = 0.0;
    if (s <= m_x.c0) {
        t = 0.0;
    } else if (s >= m_x3) {
        t = 1.0;
    } else {
        const double guess =
            parameter > 0.0 && parameter < 1.0 ? parameter : (s - m_x.c0) / (m_x3 - m_x.c0);
        t = parameterAt(m_x, m_x3, s, guess);
    }
    const double dx = m_x.first(t);
    const double dy = m_y.first(t);
    parameter = t; // Newton from here is a tangent step towards the next abscissa
    return {m_y.value(t), dy / dx, (dx * m_y.second(t) - dy * m_x.second(t)) / (dx * dx * dx)};
}

GraphPoint evaluateCubic(const CubicBezier& cubic, double s, double& parameter) {
    return CubicGraph(cubic).at(s, parameter);
}

GraphPoint evaluateCubic(const CubicBezier& cubic, double s) {
    double parameter = -1.0;
    return evaluateCubic(cubic, s, parameter);
}

GraphPoint evaluatePair(const BezierPair& pair, double s) {
    return s <= pair.first.control[3].x() ? evaluateCubic(pair.first, s)
                                          : evaluateCubic(pair.second, s);
}

double plateauDeviation(double u) {
    if (u >= 1.0) {
        return 0.0;
    }
    // 30 P(u) = 10 - 24u + 15u^2 - u^6 = (1 - u)^2 (10 - 4u - 3u^2 - 2u^3 - u^4): the double
    // root at the span edge factored out, so P keeps its relative accuracy there.
    const double w = 1.0 - u;
    return w * w * (10.0 - u * (4.0 + u * (3.0 + u * (2.0 + u)))) / 30.0;
}

double plateauDeviationSlope(double u) {
    if (u >= 1.0) {
        return 0.0;
    }
    // P'(u) = u - u^5/5 - 4/5 = (1 - u)(u^4 + u^3 + u^2 + u - 4) / 5.
    return (1.0 - u) * (u * (1.0 + u * (1.0 + u * (1.0 + u))) - 4.0) / 5.0;
}

double plateauHalfWidth(double k1, double k2, double epsilon) {
    return 4.8 * std::abs(epsilon) / std::abs(k2 - k1);
}

GraphPoint PlateauCorner::at(double s) const {
    const double a = s - p2.x();
    const double slope = a < 0.0 ? k1 : k2;
    const double line = p2.y() + slope * a;
    const double v = a / halfWidth;
    const double u = std::abs(v);
    if (u >= 1.0) {
        return {line, slope, 0.0};
    }
    // theta = polyline + A W^2 P(|v|), symmetric about S2 (see the header).
    const double a0 = (k2 - k1) / (1.6 * halfWidth); // A
    const double side = v < 0.0 ? -1.0 : 1.0;
    const double u2 = u * u;
    return {line + a0 * halfWidth * halfWidth * plateauDeviation(u),
            slope + side * a0 * halfWidth * plateauDeviationSlope(u), a0 * (1.0 - u2 * u2)};
}

} // namespace bladeaxis::scheduling

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

GraphPoint evaluateCubic(const CubicBezier& cubic, double s) {
    double low = 0.0;
    double high = 1.0;
    if (s <= cubic.control[0].x()) {
        high = 0.0;
    } else if (s >= cubic.control[3].x()) {
        low = 1.0;
    } else {
        for (int step = 0; step < 60 && high - low > 4.0 * std::numeric_limits<double>::epsilon();
             ++step) {
            const double mid = 0.5 * (low + high);
            (cubic.point(mid).x() < s ? low : high) = mid;
        }
    }
    const double t = 0.5 * (low + high);
    const Vec2 d1 = cubic.firstDerivative(t);
    return {cubic.point(t).y(), d1.y() / d1.x(), secondDerivativeAt(cubic, t)};
}

GraphPoint evaluatePair(const BezierPair& pair, double s) {
    return s <= pair.first.control[3].x() ? evaluateCubic(pair.first, s)
                                          : evaluateCubic(pair.second, s);
}

} // namespace bladeaxis::scheduling

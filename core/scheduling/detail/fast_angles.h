#pragma once
// Private to scheduling: geometry::wrapAngle / unwrapNear without the per-sample std::remainder
// call in the common cases, bit-identical to the geometry functions; and an atan2 for the
// per-sample angles (chords, axes) that is several times cheaper than the library's.

#include "core/base/units.h"
#include "core/geometry/angles.h"

#include <array>
#include <cmath>
#include <limits>

namespace bladeaxis::scheduling::detail {

inline double wrapAngle(double angle) {
    if (std::abs(angle) < units::kPi) {
        return angle; // remainder(x, 2 pi) = x exactly
    }
    // The IEEE remainder x - n 2pi is exactly representable, so the single rounding of fma
    // returns it exactly whenever n is the nearest integer, which |r| < pi proves; near the
    // half-way points (and for non-finite input) the library function decides.
    const double n = std::nearbyint(angle * (1.0 / units::kTwoPi));
    const double r = std::fma(-n, units::kTwoPi, angle);
    return std::abs(r) < units::kPi - 1e-9 ? r : geometry::wrapAngle(angle);
}

inline double unwrapNear(double angle, double reference) {
    return reference + wrapAngle(angle - reference);
}

// wrapAngle(angle) given a guess of its turn count n (the integer nearest to angle / 2 pi),
// updated for the next call: along a path the count rarely changes from one sample to the next.
// A remainder below pi - 1e-9 proves the guess right (wrapAngle's own test), and wrapAngle
// would then return the very same fma; otherwise wrapAngle decides. The same bits as wrapAngle,
// without the rounding to the nearest integer in the chain of an unwrapping loop.
inline double wrapAngleGuessed(double angle, double& turns) {
    const double r = std::fma(-turns, units::kTwoPi, angle);
    if (std::abs(r) < units::kPi - 1e-9) {
        return r;
    }
    turns = std::nearbyint(angle * (1.0 / units::kTwoPi));
    return wrapAngle(angle);
}

// unwrapNear with a guessed turn count (wrapAngleGuessed).
inline double unwrapNearGuessed(double angle, double reference, double& turns) {
    return reference + wrapAngleGuessed(angle - reference, turns);
}

namespace fast_atan {

// atan(k / kSteps), k = 0 .. kSteps, from the library once at start-up.
constexpr int kSteps = 16;
inline const std::array<double, kSteps + 1> kNodeAngles = [] {
    std::array<double, kSteps + 1> nodes{};
    for (int k = 0; k <= kSteps; ++k) {
        nodes[static_cast<std::size_t>(k)] = std::atan(static_cast<double>(k) / kSteps);
    }
    return nodes;
}();

// atan(z) for z in [0, 1]: atan(z) = atan(c) + atan(w), w = (z - c) / (1 + z c), c the nearest
// node k / 16, so |w| <= 1/32 and the Taylor series to w^9 is exact to a relative 1e-17 (the
// next term is w^11 / 11); the result is within a few ulp of the library's.
inline double atanUnit(double z) {
    const int node = static_cast<int>(z * kSteps + 0.5); // z >= 0: round to nearest
    const double k = node;
    const double c = k * (1.0 / kSteps); // exact
    const double w = (z - c) / (1.0 + z * c);
    const double w2 = w * w;
    const double series =
        w * (1.0 + w2 * (-1.0 / 3.0 + w2 * (1.0 / 5.0 + w2 * (-1.0 / 7.0 + w2 * (1.0 / 9.0)))));
    return kNodeAngles[static_cast<std::size_t>(node)] + series;
}

} // namespace fast_atan

// std::atan2(y, x) to a few ulp (absolute error below 1e-15 rad), with the same quadrants and
// signed zeros; degenerate and non-finite input goes to the library.
inline double atan2(double y, double x) {
    const double ax = std::abs(x);
    const double ay = std::abs(y);
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    // Written so that NaN fails the test (every comparison with NaN is false).
    if (!(ax < kInfinity && ay < kInfinity && (ax > 0.0 || ay > 0.0))) {
        return std::atan2(y, x);
    }
    double angle = fast_atan::atanUnit(std::min(ax, ay) / std::max(ax, ay)); // in [0, pi/4]
    if (ay > ax) {
        angle = 0.5 * units::kPi - angle;
    }
    if (std::signbit(x)) {
        angle = units::kPi - angle;
    }
    return std::signbit(y) ? -angle : angle;
}

} // namespace bladeaxis::scheduling::detail

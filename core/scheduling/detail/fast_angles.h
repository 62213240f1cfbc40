#pragma once
// Private to scheduling: geometry::wrapAngle / unwrapNear without the per-sample std::remainder
// call in the common cases, bit-identical to the geometry functions.

#include "core/base/units.h"
#include "core/geometry/angles.h"

#include <cmath>

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

} // namespace bladeaxis::scheduling::detail

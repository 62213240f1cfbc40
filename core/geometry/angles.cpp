#include "core/geometry/angles.h"

#include "core/base/units.h"

#include <cmath>

namespace bladeaxis::geometry {

double wrapAngle(double angle) {
    double wrapped = std::remainder(angle, units::kTwoPi); // in [-pi, pi]
    if (wrapped <= -units::kPi) {
        wrapped += units::kTwoPi;
    }
    return wrapped;
}

double unwrapNear(double angle, double reference) {
    return reference + wrapAngle(angle - reference);
}

std::vector<double> unwrap(std::span<const double> angles) {
    std::vector<double> result(angles.begin(), angles.end());
    for (std::size_t i = 1; i < result.size(); ++i) {
        result[i] = unwrapNear(angles[i], result[i - 1]);
    }
    return result;
}

} // namespace bladeaxis::geometry

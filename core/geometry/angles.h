#pragma once
// Angle wrapping and unwrapping (spec §1.3). Angles in rad.

#include <span>
#include <vector>

namespace bladeaxis::geometry {

// Maps any finite angle to (-pi, pi].
double wrapAngle(double angle);

// Returns `angle` plus the multiple of 2*pi that brings it closest to `reference`
// (the result lies in (reference - pi, reference + pi]).
double unwrapNear(double angle, double reference);

// Adds multiples of 2*pi so that consecutive differences lie in (-pi, pi].
std::vector<double> unwrap(std::span<const double> angles);

} // namespace bladeaxis::geometry

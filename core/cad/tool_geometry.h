#pragma once
// The cutting tool as solids of revolution about its axis, for the clearance check: the ball,
// the shank (a cylinder, or a cone tangent to the ball for a tapered tool, spec §2.3) up to the
// holder face, and the holder (a cylinder). Lengths in mm, angles in rad.
//
// Local frame: Q is the ball centre (Q = O + R V), t = (p - Q) . V along the axis towards the
// spindle and rho = |p - Q - t V| the distance from the axis. Each part is convex, so its
// signed distance (negative inside) is 1-Lipschitz, which the clearance search relies on.

#include "core/base/error.h"

#include <numbers>

namespace bladeaxis::cad {

struct ToolGeometry {
    double ballRadius = 8.0;     // R
    double taperHalfAngle = 0.0; // rad; 0 = cylindrical shank of radius R
    double stickOut = 50.0;      // from the tip O to the holder face, along the axis
    double holderRadius = 20.0;
    double holderLength = 60.0; // along the axis from the holder face
};

// The largest taper half-angle the shank model takes (exclusive): beyond it the cone is nearly a
// plane through the ball and the tool no longer describes a shank.
constexpr double kMaxTaperHalfAngle = std::numbers::pi / 3;

// Errors (InvalidArgument): non-positive or non-finite sizes, taper outside [0, 60 deg), a
// stick-out that leaves no shank above the ball.
Status validate(const ToolGeometry& tool);

// A frustum of revolution about the axis: t in [t0, t1], radius r0 + slope (t - t0).
struct AxialFrustum {
    double t0 = 0.0, t1 = 0.0, r0 = 0.0, slope = 0.0;
};

// The shank from the circle where it touches the ball to the holder face, and the holder.
AxialFrustum shankSolid(const ToolGeometry& tool);
AxialFrustum holderSolid(const ToolGeometry& tool);

// Signed distance from the point at (t, rho) to the frustum's solid of revolution.
double signedDistance(const AxialFrustum& solid, double t, double rho);

} // namespace bladeaxis::cad

#include "core/cad/tool_geometry.h"

#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace bladeaxis::cad {
namespace {

bool positive(double value) {
    return std::isfinite(value) && value > 0.0;
}

// Distance from p to the segment ab in the (t, rho) half-plane.
double segmentDistance(double t, double rho, double ta, double ra, double tb, double rb) {
    const double dt = tb - ta, dr = rb - ra;
    const double length2 = dt * dt + dr * dr;
    const double s =
        length2 > 0.0 ? std::clamp(((t - ta) * dt + (rho - ra) * dr) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(t - (ta + s * dt), rho - (ra + s * dr));
}

} // namespace

Status validate(const ToolGeometry& tool) {
    if (!positive(tool.ballRadius) || !positive(tool.stickOut) || !positive(tool.holderRadius) ||
        !positive(tool.holderLength)) {
        return makeError(ErrorCode::InvalidArgument,
                         "tool: ball radius, stick-out and holder sizes must be positive mm");
    }
    if (!std::isfinite(tool.taperHalfAngle) || tool.taperHalfAngle < 0.0 ||
        tool.taperHalfAngle >= kMaxTaperHalfAngle) {
        return makeError(ErrorCode::InvalidArgument,
                         "tool: taper half-angle must lie in [0, 60) deg, got " +
                             formatTrimmed(tool.taperHalfAngle * 180.0 / std::numbers::pi, 3) +
                             " deg");
    }
    if (tool.stickOut <= 2.0 * tool.ballRadius) {
        return makeError(ErrorCode::InvalidArgument, "tool: the stick-out (" +
                                                         formatTrimmed(tool.stickOut, 3) +
                                                         " mm) must exceed the ball diameter");
    }
    return {};
}

AxialFrustum shankSolid(const ToolGeometry& tool) {
    // The cone tangent to the ball touches it at t = -R sin(taper), radius R cos(taper).
    const double taper = tool.taperHalfAngle;
    return {-tool.ballRadius * std::sin(taper), tool.stickOut - tool.ballRadius,
            tool.ballRadius * std::cos(taper), std::tan(taper)};
}

AxialFrustum holderSolid(const ToolGeometry& tool) {
    const double face = tool.stickOut - tool.ballRadius;
    return {face, face + tool.holderLength, tool.holderRadius, 0.0};
}

double signedDistance(const AxialFrustum& solid, double t, double rho) {
    const double r1 = solid.r0 + solid.slope * (solid.t1 - solid.t0);
    const bool inside =
        t >= solid.t0 && t <= solid.t1 && rho <= solid.r0 + solid.slope * (t - solid.t0);
    if (inside) {
        const double side = (solid.r0 + solid.slope * (t - solid.t0) - rho) /
                            std::sqrt(1.0 + solid.slope * solid.slope);
        return -std::min({t - solid.t0, solid.t1 - t, side});
    }
    return std::min({segmentDistance(t, rho, solid.t0, 0.0, solid.t0, solid.r0),
                     segmentDistance(t, rho, solid.t1, 0.0, solid.t1, r1),
                     segmentDistance(t, rho, solid.t0, solid.r0, solid.t1, r1)});
}

} // namespace bladeaxis::cad

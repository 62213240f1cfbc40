#pragma once
// Analytic section profiles of the synthetic blades (spec §10.4), generated at unit chord:
// leading edge at (0, 0), trailing edge at (1, 0), suction (convex) side towards +z, the curve
// counter-clockwise in (y, z). Cosine spacing in chord puts dense points at both edges.

#include "core/base/error.h"
#include "core/blade/closed_curve.h"

namespace bladeaxis::blade {

// NACA 4-digit section, all values as fractions of the chord: camber m (0 for symmetric),
// position of maximum camber p (0 < p < 1 when m > 0) and maximum thickness t. The trailing
// edge is closed (coefficient -0.1036), so it is a sharp convex corner.
struct NacaProfile {
    double camber = 0.10;
    double camberPosition = 0.45;
    double thickness = 0.12;
};

// Turbine-type section: circular-arc camber line with turning angle `turning` (rad, the angle
// between the inlet and outlet camber tangents), a smooth thickness distribution with maximum
// `maxThickness` at mid-camber, closed by a leading-edge and a trailing-edge circle centred on
// the camber line ends. Thickness and radii are fractions of the chord.
// Known limitation: the thickness blend has zero slope at both ends (so the sides meet the edge
// circles tangentially), which makes short, weakly concave zones on the suction side next to
// the edge circles (about 2 % of the chord at the trailing edge). They add small extra backward
// runs of the fixed-lead orientation; the main concave run is still the pressure side.
struct TurbineProfile {
    double turning = 1.6; // rad (about 92 deg)
    double maxThickness = 0.15;
    double leRadius = 0.02;
    double teRadius = 0.01;
};

// Checks the parameters; messages name the quantity, value and limit.
Status validate(const NacaProfile& profile);
Status validate(const TurbineProfile& profile);

// NACA 4-digit formulas at chord fraction x in [0, 1] (unit chord).
double nacaCamber(const NacaProfile& profile, double x);
double nacaCamberSlope(const NacaProfile& profile, double x);
double nacaHalfThickness(double thickness, double x);

// Unit-chord closed sections with 2 * pointsPerSide vertices (turbine: plus the edge circles),
// starting at the trailing edge and running over the suction side first.
Result<Curve2> nacaSection(const NacaProfile& profile, int pointsPerSide);
Result<Curve2> turbineSection(const TurbineProfile& profile, int pointsPerSide);

} // namespace bladeaxis::blade

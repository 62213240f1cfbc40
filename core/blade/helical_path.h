#pragma once
// The helical reciprocal four-axis toolpath around a synthetic blade with the "original CAM"
// tool orientation (spec §10.4), used as the demo input and as the test-family generator.
//
// Path: u in [0, N] (N = revolutions), x(u) = xStart + pitch u, and the contact point P at
// normalised arc length frac(u) of the offset curve (offset_curve.h) of the section at x(u): the
// contact runs along a helix on the blade surface, as a CAM's drive curve does. The ball centre
// is Q = P + R N with N the true 3-D unit surface normal at P (from the section tangent and the
// span-wise derivative of the surface, Blade::sectionVelocity), so the ball touches the blade at
// P and does not dip into it; on a twisted blade N has an x component, and Q leaves the plane
// x(u) by up to R |N_x|. Each revolution starts at the section's phase vertex, which lies on the
// suction (convex) side (closed_curve.h: phaseIndex), and runs counter-clockwise in (y, z): the
// cutter goes round the blade right-handed about +x while advancing along +x. The last
// revolution is closed by a record at u = N. Samples are placed by adaptive bisection so that the
// middle of every chord of Q lies within `chordalTolerance` of the centre curve and no chord
// exceeds `maxStep`: the points are dense at the edges, where the centre curve turns fast.
//
// Orientation (four axes: the B head keeps its tilt B0, only the azimuth about x is free):
// phi = azimuth of N in the (y, z) plane (the direction of the section normal n) + lead
// (towards the feed direction, i.e. counter-clockwise) + optional seeded Gaussian noise;
//     V = (sin B0, cos B0 cos phi, cos B0 sin phi),   O = Q - R V  (optionally rounded).
// This fixed-lead orientation turns backwards wherever n does, i.e. in concave runs.

#include "core/base/error.h"
#include "core/base/units.h"
#include "core/blade/blade.h"
#include "core/toolpath/toolpath.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace bladeaxis::blade {

// The most points a generated path may have (10 million records, about 2 GB while generating):
// a revolution count or tolerance beyond it is refused instead of exhausting memory.
inline constexpr std::size_t kMaxGeneratedPoints = 10'000'000;

struct HelicalPathSpec {
    double toolRadius = 8.0;                           // R, mm
    double pitch = 0.5;                                // mm of x per revolution, > 0
    int revolutions = 8;                               // N >= 1
    double tiltB0 = units::degToRad(5.0);              // rad, |B0| < 90 deg
    double leadAngle = units::degToRad(15.0);          // rad, |lead| < 90 deg
    double chordalTolerance = 0.01;                    // mm, [1e-4, 1]
    double maxStep = 1.0;                              // mm, longest chord of Q
    double feed = units::perMinuteToPerSecond(3000.0); // mm/s
    double leadNoise = 0.0;                            // rad, standard deviation (0 = none)
    double roundTipTo = 0.0;                           // mm grid for O (0 = exact), e.g. 1e-3
    std::uint64_t seed = 1;                            // for the noise
    std::optional<double> xStart;                      // mm; default: the span start
};

// Everything a test needs to check the path, one entry per record of `path`.
struct GeneratedPath {
    toolpath::Toolpath path;
    std::vector<Vec3> contact;     // P on the blade surface (on the section at sectionX), in W
    std::vector<Vec3> normal;      // N, the unit outward surface normal at P
    std::vector<Vec3> centre;      // Q = P + R N (exact; O + R V equals it before rounding)
    std::vector<double> sectionX;  // x of P
    std::vector<double> parameter; // u
    std::vector<int> revolution;   // floor(u); the closing record belongs to the last one
    double minConcaveRadius = 0.0; // of the swept sections, mm (+inf when convex)
};

Status validate(const HelicalPathSpec& spec);

Result<GeneratedPath> generateHelicalPath(const Blade& blade, const HelicalPathSpec& spec);

} // namespace bladeaxis::blade

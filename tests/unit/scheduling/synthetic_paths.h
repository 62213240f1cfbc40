#pragma once
// Synthetic inputs for the scheduling tests (spec §10.4), written here so that the tests do not
// depend on the blade generator: NACA-like sections, their exact ball-centre offsets, and
// helical paths with the "original CAM" fixed-lead orientation.

#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"

#include <vector>

namespace bladeaxis::scheduling::testing {

// Closed counter-clockwise NACA 4-digit section (closed trailing edge), chord along +u,
// cosine spacing with `perSide` points per surface; m, p, t as fractions.
std::vector<Vec2> nacaSection(double m, double p, double t, double chord, std::size_t perSide);

// Regular n-gon of circumradius r, counter-clockwise, starting at angle phase (rad).
std::vector<Vec2> regularPolygon(std::size_t n, double r, double phase = 0.0);

struct OffsetCurve {
    std::vector<Vec2> points;  // ball centres, closed (last != first), counter-clockwise
    std::vector<Vec2> normals; // outward unit normals of the section at the contact points
};

// Exact offset by `radius` (miter at gentle vertices, arcs of <= maxArcStepRad at sharp convex
// ones), with the section's outward normals.
OffsetCurve offsetSection(const std::vector<Vec2>& section, double radius, double maxArcStepRad);

struct HelixOptions {
    double toolRadius = 8.0;              // mm
    double pitchMm = 0.5;                 // axial advance per revolution
    double revolutions = 3.0;             // may be fractional
    double startFraction = 0.3;           // phase of the first point (fraction of the closed curve)
    double leadRad = 0.2617993877991494;  // 15 deg towards the feed
    double tiltRad = 0.08726646259971647; // B0 = 5 deg
    double twistRadPerMm = 0.0;           // section rotation about the axis per mm of x
    bool mirror = false;                  // y -> -y: the feed turns about -x
};

// Helical path around the curve: x grows with the arc-length fraction; V = (sin B0, cos B0 d)
// with d = cos(lead) n + sin(lead) t in the (y, z) plane.
ScheduleInput helicalPath(const OffsetCurve& curve, const HelixOptions& options);

// The Appendix B section: NACA-like m = 0.10, p = 0.45, t = 0.12, chord 80 mm, 241 per side.
OffsetCurve appendixBCurve(double toolRadius = 8.0);

} // namespace bladeaxis::scheduling::testing

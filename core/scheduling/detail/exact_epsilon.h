#pragma once
// Private to smoothing: the exact epsilon rule of spec §5.4 without a blind bisection.
//
// Homothety (§5.3): every control point of a corner pair is P2 + |epsilon| * (a fixed offset),
// so the vertical deviation from the polyline at offset a = S - S2 is dev(a, m) = m E(a / m)
// (m = |epsilon|, E the deviation of the unit pair), non-decreasing in m and at most m. Each
// sample therefore bounds m on its own, in closed form up to one cubic root, and only samples
// whose room is below the current bound need that root. The dense parameter checks of §5.4 are
// then settled by a sufficient condition on the piecewise-linear channel (the room is linear
// between samples, the deviation monotone on each side of S2); where that condition cannot
// decide, the original predicate and, if needed, the original bisection run, so the result is
// the same supremum the 40-step bisection approximates (to ~1e-12 relative, not 2^-40).

#include "core/scheduling/bezier_corner.h"
#include "core/scheduling/detail/corner_channel.h"

namespace bladeaxis::scheduling::detail {

struct CornerGeometry {
    Vec2 p2;                // the polyline vertex (S2, theta2)
    double kIn = 0.0;       // incoming polyline slope, rad/mm
    double kOut = 0.0;      // outgoing polyline slope, rad/mm
    double sign = 1.0;      // +1 valley (curve above the polyline), -1 crest
    BezierPair unitOffsets; // the pair at |epsilon| = 1 as offsets from P2, y multiplied by sign
};

// Builds the unit offsets from the pair at epsilon = sign * 1.
CornerGeometry cornerGeometry(const Vec2& p2, double kIn, double kOut, double sign,
                              const BezierPair& unitPair);

// The largest |epsilon| in [0, geometric] for which the pair passes pairFeasible.
double exactEpsilon(const CornerGeometry& corner, double geometric, const ChannelView& channel,
                    int checks, int bisectionSteps);

// The exact rule for the plateau corner [X]: the largest half-width W in [0, geometric] for
// which the corner stays in the channel at every sample of its span and at 2 checks + 1 evenly
// spaced abscissae. Per-sample bounds in closed form up to one polynomial root (homothety in W),
// then the predicate, and the bisection only where the sufficient condition cannot decide.
double exactPlateauHalfWidth(const Vec2& p2, double k1, double k2, double geometric,
                             const ChannelView& channel, int checks, int bisectionSteps);

} // namespace bladeaxis::scheduling::detail

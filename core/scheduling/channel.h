#pragma once
// Spec §2: the feasible orientation channel. Raw limits in absolute angles (unwrapped along the
// whole path), the concave-run rule, taper/safety angles, optional global visibility and
// despiking, and the lossless monotone hull with margin and local pinch relief (§2.5).

#include "core/base/default_init.h"
#include "core/geometry/vec.h"
#include "core/scheduling/curvature_states.h"
#include "core/scheduling/tangents.h"

#include <span>
#include <vector>

namespace bladeaxis::scheduling {

struct RawChannel {
    DefaultInitVector<double> thetaMin; // absolute backward limit, rad
    DefaultInitVector<double> thetaMax; // absolute forward limit, rad
};

// §2.1 convex formula everywhere, then §2.2 for every sample of a concave run:
// thetaMax = thetaMax(exit), thetaMin = thetaMin(entry). `inwardRad` = taper + safety angle.
// The per-sample limits are computed on the context's threads (core/base/execution.h).
RawChannel buildRawChannel(const TangentField& tangents, std::span<const ConcaveRun> runs,
                           double inwardRad);

// §2.4 [X] global visibility: clip thetaMax_i by the directions to the next `reach` points
// and thetaMin_i by the directions to the previous ones (each relative to the local limit).
void clipGlobalVisibility(RawChannel& channel, std::span<const Vec2> points, std::size_t reach);

// §2.4 [X] lead band: thetaMax_i <= theta_n,i + maxRad and thetaMin_i >= theta_n,i + minRad,
// with theta_n the outward normal of the centre curve: the chord bisector ang(e+) - tau / 2
// turned by -pi/2 (feed counter-clockwise), on the branch of the unwrapped forward angle. Where
// the normal turns backwards (concave runs), the channel follows it: a pinch for §2.5.
void clipLeadBand(RawChannel& channel, const TangentField& tangents, double minRad, double maxRad);

// §4.6 [A, non-conservative] replace isolated downward outliers of thetaMax (upward of
// thetaMin) by the centred median of 7. Returns how many samples changed.
std::size_t despikeChannel(RawChannel& channel);

struct MonotoneHull {
    std::vector<double> lo, hi;             // LO, HI: non-decreasing, margin-shrunk hull, rad
    std::vector<double> lo0, hi0;           // HULL0: hull of the raw channel (no margin)
    std::vector<double> marginLo, marginHi; // the margin actually applied per sample
    bool pinched = false;                   // the margin was reduced somewhere (§2.5)
    bool infeasible = false;                // LO0 > HI0 somewhere: no monotone path exists
    double minWidth = 0.0;                  // min(HI - LO), rad
};

// Running max of lo from the left, running min of hi from the right. Where the full margin
// would pinch, the margin is reduced locally so that every pair k <= l stays compatible.
MonotoneHull monotoneHull(std::span<const double> thetaMin, std::span<const double> thetaMax,
                          double margin);

// monotoneHull's LO, HI, flags and minWidth (the same bits) without HULL0 and the margins
// (left empty): three passes and two arrays instead of six, for the layers of large paths.
MonotoneHull monotoneBounds(std::span<const double> thetaMin, std::span<const double> thetaMax,
                            double margin);

} // namespace bladeaxis::scheduling

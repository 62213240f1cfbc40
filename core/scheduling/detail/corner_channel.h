#pragma once
// Private to smoothing: the raw channel seen by one Bezier corner (spec §5.4), and the exact-rule
// feasibility predicate of a corner pair (samples in its span and dense parameter checks).

#include "core/scheduling/bezier_corner.h"

#include <span>
#include <utility>

namespace bladeaxis::scheduling::detail {

// Feasibility tolerance of the exact rule, rad: the same as the key point rule's order of
// magnitude, far below any angle that matters, far above round-off of theta ~ 10 rad.
constexpr double kFeasibilityTolerance = 1e-12;

// Channel bounds at any S: linear interpolation between samples (s sorted), shrunk by the final
// clearance.
struct ChannelView {
    std::span<const double> s, rawMin, rawMax;
    double clearance = 0.0;

    std::pair<double, double> at(double x) const;
    // Index of the first sample with s >= x and of the first with s > x.
    std::size_t lowerIndex(double x) const;
    std::size_t upperIndex(double x) const;
};

// The exact rule's predicate: the pair within the channel at every sample in its span and at
// `checks` + 1 parameter values per cubic.
bool pairFeasible(const BezierPair& pair, const ChannelView& channel, int checks);

} // namespace bladeaxis::scheduling::detail

#pragma once
// The controller-like filter of spec §8.1: what a CNC's interpolator does to a piecewise-linear
// program, approximated as the axis resampled every millisecond at constant feed and smoothed by
// a centred moving average applied twice (a triangular FIR). Its derivatives measure the tool
// orientation rather than the CL discretisation (raw second differences of G-code are impulses).

#include "core/base/progress.h"

#include <span>
#include <vector>

namespace bladeaxis::analysis {

struct FilteredAxis {
    double step = 1e-3;                                         // s between samples
    std::vector<double> position, velocity, acceleration, jerk; // per step, from t = 0
};

// s: strictly increasing path parameter (mm), position: axis samples, feed > 0 (mm/s),
// windowSeconds >= 0 (0: no smoothing). Outside the path the axis continues its motion (the
// series is extended by point reflection about its ends): an axis already moving at the start
// of the pass shows no start-up peak.
FilteredAxis filterAxis(std::span<const double> s, std::span<const double> position, double feed,
                        double windowSeconds, double step = 1e-3);

// Centred moving average over `width` samples (odd; even widths grow by one), edges padded by
// point reflection about the end samples, so a straight run stays exactly straight.
std::vector<double> movingAverage(std::span<const double> values, std::size_t width);
// The same into `out` (resized; not `values`' own storage).
void movingAverageInto(std::span<const double> values, std::size_t width, std::vector<double>& out);
// The same over `values` itself, bit for bit movingAverageInto's, with no second series.
void movingAverageInPlace(std::vector<double>& values, std::size_t width);

// filterAxis's smoothed positions alone, into `out`, smoothed in place: what the derivatives
// are taken from without keeping velocity, acceleration and jerk series (24 bytes per
// millisecond of the pass and axis) or a second series of positions (8). False, with `out`
// unfinished, when `cancel` is set before a smoothing pass (each a tenth of a second or more
// on tens of millions of milliseconds).
bool smoothedPositions(std::span<const double> s, std::span<const double> position, double feed,
                       double windowSeconds, double step, std::vector<double>& out,
                       const CancelToken* cancel = nullptr);

// Linear interpolation of a uniformly stepped series at time t (clamped to its ends).
double sampleAt(const std::vector<double>& series, double step, double t);

} // namespace bladeaxis::analysis

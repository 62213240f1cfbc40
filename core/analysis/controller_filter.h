#pragma once
// The controller-like filter of spec §8.1: what a CNC's interpolator does to a piecewise-linear
// program, approximated as the axis resampled every millisecond at constant feed and smoothed by
// a centred moving average applied twice (a triangular FIR). Its derivatives measure the tool
// orientation rather than the CL discretisation (raw second differences of G-code are impulses).

#include <span>
#include <vector>

namespace bladeaxis::analysis {

struct FilteredAxis {
    double step = 1e-3;                                         // s between samples
    std::vector<double> position, velocity, acceleration, jerk; // per step, from t = 0
};

// s: strictly increasing path parameter (mm), position: axis samples, feed > 0 (mm/s),
// windowSeconds >= 0 (0: no smoothing). The axis holds its end values outside the path.
FilteredAxis filterAxis(std::span<const double> s, std::span<const double> position, double feed,
                        double windowSeconds, double step = 1e-3);

// Centred moving average over `width` samples (odd; even widths grow by one), edges padded with
// the end values.
std::vector<double> movingAverage(std::span<const double> values, std::size_t width);

// Linear interpolation of a uniformly stepped series at time t (clamped to its ends).
double sampleAt(const std::vector<double>& series, double step, double t);

} // namespace bladeaxis::analysis

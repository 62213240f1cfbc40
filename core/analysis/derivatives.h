#pragma once
// Axis derivatives along the path parameter at constant feed (spec §8.1). Building blocks of
// analyseAxisMotion, public so that they can be tested and reused on any sampled axis.

#include "core/analysis/axis_profile.h"

#include <span>
#include <vector>

namespace bladeaxis::analysis {

// Differentiates `position` (samples at the strictly increasing path parameter s, mm) and
// returns the series with velocity, acceleration, jerk, peaks and percentiles at feed F (mm/s).
// Errors: InvalidArgument (sizes differ, s not strictly increasing, F not positive),
// Geometry (a non-finite value, or derivatives that overflow).
// filterSeconds is the window of DerivativeMethod::Filtered (ignored otherwise); its peaks are
// taken over the whole 1 ms series, its per-sample values interpolated at the sample times.
// knots (DerivativeMethod::Spline only): ascending sample indices with the first and the last
// (motionKnots); the spline is fitted through them and evaluated at every sample. Empty: all.
Result<AxisSeries> differentiateAxis(std::span<const double> s, std::vector<double> position,
                                     double feed, DerivativeMethod method,
                                     double filterSeconds = 0.008,
                                     std::span<const std::size_t> knots = {});

// The p-quantile (0 <= p <= 1) of |values|, linear interpolation between order statistics
// (numpy's default). 0 for an empty input. O(n).
double absPercentile(std::span<const double> values, double p);

} // namespace bladeaxis::analysis

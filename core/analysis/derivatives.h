#pragma once
// Axis derivatives along the path parameter at constant feed (spec §8.1). Building blocks of
// analyseAxisMotion, public so that they can be tested and reused on any sampled axis.

#include "core/analysis/axis_profile.h"

#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace bladeaxis::analysis {

// Differentiates `position` (samples at the strictly increasing path parameter s, mm) and
// returns the series with velocity and acceleration, the peaks (the jerk's too), percentiles at
// feed F (mm/s) and the range of the positions.
// Errors: InvalidArgument (sizes differ, s not strictly increasing, F not positive),
// Geometry (a non-finite value, derivatives that overflow, a filtered pass longer than
// kMaxFilterSamples milliseconds).
// filterSeconds is the window of DerivativeMethod::Filtered (ignored otherwise); its peaks and
// percentiles are taken over the whole 1 ms series, its per-sample values interpolated at the
// sample times.
// knots (DerivativeMethod::Spline only): ascending sample indices with the first and the last
// (motionKnots); the spline is fitted through them and evaluated at every sample. Empty: all.
// The most samples DerivativeMethod::Filtered resamples an axis into (one per millisecond of
// the pass at its feed): 50 million, about 13.9 hours of motion and 800 MB per axis under way.
// A longer pass (a far-off point, a very low feed) is refused (Geometry) naming this limit and
// the spline derivatives, which take the program's own samples, instead of exhausting memory.
inline constexpr std::size_t kMaxFilterSamples = 50'000'000;

Result<AxisSeries> differentiateAxis(std::span<const double> s, std::vector<double> position,
                                     double feed, DerivativeMethod method,
                                     double filterSeconds = 0.008,
                                     std::span<const std::size_t> knots = {});

// differentiateAxis of several axes sampled at the same s, one result per axis, each the one
// differentiateAxis gives. The spline methods fit every axis through the same knots, so the
// spline system is eliminated once for all axes, and s is checked once. The axes are then
// differentiated on the context's threads (core/base/execution.h), each axis on one thread, so the
// results are the same on any number.
std::vector<Result<AxisSeries>> differentiateAxes(std::span<const double> s,
                                                  std::span<const std::vector<double>> positions,
                                                  double feed, DerivativeMethod method,
                                                  double filterSeconds = 0.008,
                                                  std::span<const std::size_t> knots = {});

// The positions of axis k at the samples: a view of the caller's own, or of `scratch` filled
// for the call. Called once per axis, on the thread that differentiates it.
using PositionsOf =
    std::function<std::span<const double>(std::size_t axis, std::vector<double>& scratch)>;

// differentiateAxes of `axes` axes whose positions are handed out one axis at a time: only the
// axes being differentiated (one per thread) have positions and spline moments at once. An axis
// that starts after `cancel` is set is not differentiated, and a spline fit under way stops
// within 65,536 samples: their results are ErrorCode::Cancelled. With a budget
// (AxisProfileOptions::filterSeriesBytesAtOnce) the filter's axes go one at a time when their
// millisecond series would pass it together.
std::vector<Result<AxisSeries>>
differentiateAxes(std::span<const double> s, std::size_t axes, const PositionsOf& positionsOf,
                  double feed, DerivativeMethod method, double filterSeconds = 0.008,
                  std::span<const std::size_t> knots = {}, const CancelToken* cancel = nullptr,
                  double filterSeriesBytesAtOnce = 0.0);

// The p-quantile (0 <= p <= 1) of |values|, linear interpolation between order statistics
// (numpy's default). 0 for an empty input. O(n).
double absPercentile(std::span<const double> values, double p);

// absPercentile of `count` values added one at a time, without storing them: only the
// count - k largest magnitudes the quantile depends on are kept, in a heap (0.1 % of the values
// for p = 0.999).
class AbsPercentile {
  public:
    AbsPercentile(std::size_t count, double p);

    void add(double v) {
        // NaN fails the comparison and is kept: it ranks above every number.
        if (!(std::abs(v) <= m_smallestKept)) {
            keep(v);
        }
    }

    // After all `count` values.
    double value() const;

  private:
    void keep(double v);

    std::vector<double> m_kept; // min-heap of the largest magnitudes so far
    std::size_t m_keep = 0;
    double m_fraction = 0.0;
    double m_smallestKept = -HUGE_VAL; // every value is kept until the heap is full
};

} // namespace bladeaxis::analysis

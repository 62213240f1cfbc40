#pragma once
// Spec §1.6: smoothed curvature, convex/concave states with hysteresis, concave runs (merged
// over short gaps, short runs dropped) and the concave-convex altered points.

#include "core/base/default_init.h"

#include <cstddef>
#include <span>
#include <vector>

namespace bladeaxis::scheduling {

enum class CurvatureState : unsigned char { Convex, Concave };

struct ConcaveRun {
    std::size_t entry = 0;      // first concave sample A_r (convex -> concave altered point)
    std::size_t exit = 0;       // first convex sample after the run B_r; == sample count if none
    double lengthMm = 0.0;      // arc length from entry to exit (or to the path end)
    double absTurningRad = 0.0; // sum of |tau| over the run (tie-break of the main run, §1.7)
};

struct CurvatureSettings {
    double windowMm = 2.0;         // w
    double hysteresisPerMm = 1e-4; // kappa_h
    double mergeGapMm = 16.0;      // L_gap
    double minRunMm = 16.0;        // L_min
};

struct CurvatureAnalysis {
    DefaultInitVector<double> smoothedCurvature;  // kappa-bar_i, 1/mm
    DefaultInitVector<CurvatureState> hysteresis; // raw hysteresis states (before merge/drop)
    DefaultInitVector<CurvatureState> state;      // states after merging and dropping runs
    std::vector<ConcaveRun> runs;                 // kept runs in feed order
};

// Prefix sums of the arc-length weights of the samples and of their weighted curvature, the
// smoothing's inputs: n + 1 each, [0] = 0, summed in sample order (a sum in another order
// would round differently, so this is one chain through the path).
struct CurvatureWeights {
    DefaultInitVector<double> weighted, weight;
};
CurvatureWeights curvatureWeights(std::span<const double> arcLength,
                                  std::span<const double> curvature);

// `curvature` is the per-sample estimate of TangentField; `turning` the per-sample tau. The
// smoothing runs on the context's threads (core/base/execution.h), with the same result as on one.
CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   std::span<const double> curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings);
// The same, the smoothed curvature written over the given one's storage (8 bytes per sample
// fewer where the scheduling makes its channel stage).
CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings);
// The same with the weights already summed (curvatureWeights of the same samples), so that
// their sum can run beside other serial work. They are freed once the smoothing has read them.
CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   CurvatureWeights&& weights, std::span<const double> turning,
                                   const CurvatureSettings& settings);

// Indices where the state differs from the predecessor's, in feed order (the altered points),
// found on the context's threads.
std::vector<std::size_t> alteredPoints(std::span<const CurvatureState> states);

} // namespace bladeaxis::scheduling

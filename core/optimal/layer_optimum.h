#pragma once
// The physical-limit baseline of spec §9: per layer, the best theta(S) under the same hull,
// monotonicity and junction/end-slope constraints as the S-theta engine: `optimal-qp`, the
// smoothest (minimum sum w_i D2_i^2, about the integral of theta''^2), and `optimal-lp`, the
// minimum peak |D2_i|, both solved by the interior-point method of interior_point.h.

#include "core/base/error.h"
#include "core/optimal/interior_point.h"
#include "core/scheduling/schedule.h"

#include <span>
#include <vector>

namespace bladeaxis::optimal {

// Spec §9.1 for one layer: hull bounds, the engine's junction values, zero end slopes; the first
// and last layers of a path keep their outer end free (§3.3).
enum class Objective { SmoothestQp, MinimumPeakLp };

struct LayerBounds {
    std::vector<double> s, lower, upper; // mm, rad (relative to the layer's junction angle)
    double start = 0.0, end = 0.0;       // junction values, rad
    bool freeStart = false, freeEnd = false;
    // The zero end slope is a flat first/last step (spec §9.1) where the hull allows one. At a
    // pinched base point (§4.6: the junction value lies outside the hull at the neighbouring
    // sample, as at the fallback base point of a section without a concave run) no flat step
    // fits, and the engine rises into the base point with theta' = 0 only analytically. There
    // the condition is a mirrored ghost sample (theta_-1 = theta_1), the usual discrete form of
    // theta' = 0: its second difference 2 (theta_1 - theta_0) / h_0^2 joins the objective.
    bool mirroredStart = false, mirroredEnd = false;
    // The value is held, the slope is not: the engine's outer ends (spec §3.3: the input
    // orientation clamped into the hull, no lead segment).
    bool freeStartSlope = false, freeEndSlope = false;
};

// What the optimum is held to.
enum class OptimumConstraints {
    // Like for like with the engine's output: the monotone hull of the raw channel (the channel
    // the engine's schedule is checked against; the best preset may use all of its margin) and
    // the engine's values at every layer end, with a zero slope where the engine has one (at
    // the junctions; the path's outer ends hold the value only, as the engine's do).
    LikeTheEngine,
    // Spec §9.1 as written: the engine's hull shrunk by its margin, the outer ends free. The
    // engine may leave this hull (into its margin), so it is not the engine's problem.
    ShrunkHull,
};

// The junction values are the engine's; an end is mirrored where a flat step is infeasible.
LayerBounds boundsOf(const scheduling::LayerResult& layer, bool firstLayer, bool lastLayer,
                     OptimumConstraints constraints = OptimumConstraints::LikeTheEngine);

struct LayerOptimum {
    std::vector<double> theta;
    double peakSecondDifference = 0.0;   // max |D2_i| (mirrored ends included), rad/mm^2
    double secondDifferenceEnergy = 0.0; // sum w_i D2_i^2 (mirrored ends included)
    int iterations = 0;
    double relativeResidual = 0.0; // of the interior point's KKT conditions
    double seconds = 0.0;
};

// The two problems as the interior point solves them (for cross-checks with other solvers):
// variables theta (and, for the LP, the peak's epigraph variable last). Bounds must be valid
// (at least 4 samples, S increasing).
ConvexProgram smoothestProgram(const LayerBounds& bounds);
ConvexProgram minimumPeakProgram(const LayerBounds& bounds);

// Errors: InvalidArgument (fewer than 4 samples, sizes, an empty hull), Infeasible (the solver
// did not converge to a feasible point).
Result<LayerOptimum> smoothestLayer(const LayerBounds& bounds);
Result<LayerOptimum> minimumPeakLayer(const LayerBounds& bounds);

// The samples of a layer (its S) the optimum is solved on: every sample, or, when that leaves at
// least 4, those not a short chord (under a tenth of the median) from the previous kept one.
// The channel metrics measure every method's theta'' on the same samples
// (compare::measureInChannel), so that the optimum is never worse than a feasible schedule on
// its own objective.
std::vector<std::size_t> problemSamples(std::span<const double> s);

// theta at every sample of `bounds` as optimalPath computes it: the layer solved without the
// samples a short chord (under a tenth of the median) from the previous one, which are then
// interpolated linearly within their own bounds (see docs/figures.md).
Result<std::vector<double>> optimalLayer(const LayerBounds& bounds, Objective objective);

// The optimal schedule of a whole path: every layer of the engine's result optimised, as an
// absolute in-plane angle per input sample (merged duplicates share their sample's angle).
struct PathOptimum {
    std::vector<double> thetaAbsolute;
    double seconds = 0.0; // wall time of all layers
    std::size_t layers = 0;
};
Result<PathOptimum> optimalPath(const scheduling::ScheduleResult& reference, Objective objective);

// The two objectives of spec §9.1 (peak |D2_i| and sum w_i D2_i^2 over the interior samples)
// of any schedule.
double peakSecondDifference(std::span<const double> s, std::span<const double> theta);
double secondDifferenceEnergy(std::span<const double> s, std::span<const double> theta);

// The objectives of the problem `bounds` for any schedule of its samples: the interior D2_i
// and, at a mirrored end, the ghost sample's. What the optimum minimises, so a feasible
// schedule (the engine's) can be compared with it like for like.
double peakSecondDifference(const LayerBounds& bounds, std::span<const double> theta);
double secondDifferenceEnergy(const LayerBounds& bounds, std::span<const double> theta);

} // namespace bladeaxis::optimal

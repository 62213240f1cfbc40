#pragma once
// The physical-limit baseline of spec §9: per layer, the smoothest theta(S) (minimum
// sum w_i D2_i^2, about the integral of theta''^2; `optimal-qp`) under the same hull,
// monotonicity and junction/end-slope constraints as the S-theta engine, solved by the ADMM of
// admm.h. The min-peak LP (`optimal-lp`) is not provided: this ADMM does not converge on it to
// a useful accuracy (no curvature; tried with row scaling and 4e5 iterations), and a simplex or
// interior-point LP solver of our own was out of this change's scope.

#include "core/base/error.h"
#include "core/optimal/admm.h"
#include "core/scheduling/schedule.h"

#include <span>
#include <vector>

namespace bladeaxis::optimal {

// Spec §9.1 for one layer: hull bounds, the engine's junction values, zero end slopes; the first
// and last layers of a path keep their outer end free (§3.3).
struct LayerBounds {
    std::vector<double> s, lower, upper; // mm, rad (relative to the layer's junction angle)
    double start = 0.0, end = 0.0;       // junction values, rad
    bool freeStart = false, freeEnd = false;
};

LayerBounds boundsOf(const scheduling::LayerResult& layer, bool firstLayer, bool lastLayer);

struct LayerOptimum {
    std::vector<double> theta;
    double peakSecondDifference = 0.0;   // max |D2_i|, rad/mm^2
    double secondDifferenceEnergy = 0.0; // sum w_i D2_i^2
    QpSolution solver;
    double seconds = 0.0;
};

// Errors: InvalidArgument (fewer than 4 samples, sizes, an empty hull), Infeasible (the solver
// did not converge to a feasible point).
Result<LayerOptimum> smoothestLayer(const LayerBounds& bounds, const AdmmSettings& settings = {});

// The smoothest schedule of a whole path: every layer of the engine's result optimised, as an
// absolute in-plane angle per input sample (merged duplicates share their sample's angle).
struct PathOptimum {
    std::vector<double> thetaAbsolute;
    double seconds = 0.0; // wall time of all layers
    std::size_t layers = 0;
};
Result<PathOptimum> smoothestPath(const scheduling::ScheduleResult& reference);

// D2_i of spec §9.1 at the interior samples (ends 0), and the two objectives of any schedule.
std::vector<double> secondDifferences(std::span<const double> s, std::span<const double> theta);
double peakSecondDifference(std::span<const double> s, std::span<const double> theta);
double secondDifferenceEnergy(std::span<const double> s, std::span<const double> theta);

} // namespace bladeaxis::optimal

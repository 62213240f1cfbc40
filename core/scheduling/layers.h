#pragma once
// Spec §1.7: base points (exit of the main concave run of each revolution, or a fallback at the
// flattest place) and the layers between them.

#include "core/scheduling/curvature_states.h"
#include "core/scheduling/schedule_parameters.h"

#include <cstddef>
#include <span>
#include <vector>

namespace bladeaxis::scheduling {

struct LayerSpan {
    std::size_t first = 0;  // distinct-sample index of the layer start (a base point or 0)
    std::size_t last = 0;   // distinct-sample index of the layer end (shared with the next layer)
    bool startFree = false; // path start: free end value (§3.3)
    bool endFree = false;   // path end: free end value
    bool fallbackBase = false; // a base point of this layer is a fallback (no concave run)
};

struct LayerSplit {
    std::vector<std::size_t> basePoints; // increasing, never 0 or the last sample
    std::vector<bool> fallback;          // per base point
    std::vector<LayerSpan> layers;       // [0, b1], [b1, b2], ..., [bK, n-1]
};

// `forwardAngle` is the unwrapped tangent angle Phi (its change is the path's turning);
// `smoothedCurvature` kappa-bar selects fallback base points.
LayerSplit splitLayers(std::span<const double> forwardAngle,
                       std::span<const double> smoothedCurvature, std::span<const ConcaveRun> runs,
                       BasePointRule rule);

} // namespace bladeaxis::scheduling

#pragma once
// Spec §2.6, §3.1, §3.3: everything one layer needs after the channel is built. Layers are
// independent from here on, so they can be scheduled in parallel.

#include "core/scheduling/channel.h"
#include "core/scheduling/layers.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/schedule.h"

#include <span>
#include <string>
#include <vector>

namespace bladeaxis::scheduling {

struct LayerProblem {
    LayerSpan span;         // distinct-sample range
    double reference = 0.0; // absolute angle of relative 0 (the start value), rad
    std::vector<double> s;  // S from the layer start, mm
    std::vector<double> rawMin, rawMax, lo, hi, original; // relative, rad
    double startValue = 0.0;                              // relative (0 by construction)
    double endValue = 0.0; // relative (theta_e for intermediate layers)
    bool shortLayer = false;
    std::vector<LayerStatus> flags;
    std::vector<std::string> warnings;
};

// Hulls per layer (margins: one per layer of the split), junctions J_k = min(HI_k(0),
// HI_{k-1}(end)), free end values clamped into the hull (and monotone), and the feasibility checks
// of §2.5 and §4.6. Of the plane path it reads the arc length and the original angle only (the
// scheduling frees the rest before).
std::vector<LayerProblem> buildLayerProblems(const PlanePath& path, const RawChannel& channel,
                                             const LayerSplit& split,
                                             std::span<const double> margins, double shortLengthMm);

} // namespace bladeaxis::scheduling

#pragma once
// Spec §3.4, §4, §5 for one layer: lead choice (fixed or golden-section auto), linearisation,
// corner smoothing and analytic evaluation at the samples. A pure function of its problem.

#include "core/scheduling/layer_problem.h"
#include "core/scheduling/schedule.h"
#include "core/scheduling/smoothing.h"

#include <string>
#include <vector>

namespace bladeaxis::scheduling {

// The reviewer-facing name of what limited a corner's size (LayerResult::Corner).
LayerResult::Corner::Bound cornerBound(CornerLimit limit);

struct LayerOutcome {
    LayerResult result;
    std::vector<std::string> warnings;
};

// inputIndex maps layer samples to input indices. The problem's per-sample vectors are moved
// into the result.
LayerOutcome scheduleLayer(LayerProblem problem, const ScheduleParameters& parameters,
                           std::vector<std::size_t> inputIndex, std::size_t layerNumber);

// 3-point non-uniform differences (spec §8.1), exact for quadratics; used for kept originals.
void finiteDifferences(std::span<const double> s, std::span<const double> values,
                       std::vector<double>& first, std::vector<double>& second);

} // namespace bladeaxis::scheduling

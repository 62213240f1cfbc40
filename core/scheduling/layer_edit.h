#pragma once
// Re-smoothing of one layer from key points the engineer edited (the GUI's S-theta editor).
// The layer's channel, hull and samples stay; the polyline, corners and theta(S) are rebuilt.

#include "core/base/error.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"
#include "core/scheduling/schedule_parameters.h"

#include <span>

namespace bladeaxis::scheduling {

// `vertices` become the new polyline, (S, theta) relative to the layer reference, increasing
// S. Each S is snapped to the nearest layer sample. The ends must stay where they are (they
// join the neighbouring layers), theta must be monotone along the polyline, and every segment
// must lie inside the monotone hull [lo, hi] (within parameters.keyToleranceRad); otherwise
// InvalidArgument says which rule the edit breaks.
Result<LayerResult> resmoothLayer(const LayerResult& layer, std::span<const Vec2> vertices,
                                  const ScheduleParameters& parameters);

} // namespace bladeaxis::scheduling

#pragma once
// An engineer's changes to single layers (the GUI's S-theta editor), kept with the job and
// applied on every run, so that the GUI and `--batch` write the same program from the same job.

#include "core/base/error.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule_parameters.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace bladeaxis::scheduling {

struct LayerOverride {
    std::size_t layer = 0; // layer number in feed order
    // Per-layer settings; unset: the job's. A preset replaces the layer's own settings (margin,
    // lead, key points, corners); the channel-wide ones (taper, tangents, curvature,
    // visibility) stay the job's, because the channel is shared by all layers.
    std::optional<Preset> preset;
    std::optional<double> marginRad;
    std::optional<EpsilonRule> epsilonRule;
    std::optional<double> leadFraction; // rho; sets the fixed lead mode
    // The edited polyline, (S, theta) relative to the layer reference; empty: the engine's own.
    // Applied with resmoothLayer after the layer is scheduled with the settings above.
    std::vector<Vec2> keyPoints;

    bool operator==(const LayerOverride&) const = default;
};

// The parameters the engine uses for one layer: the job's, changed by the override.
ScheduleParameters layerParameters(const ScheduleParameters& job, const LayerOverride& change);

// The override of `layer`, or nullptr.
const LayerOverride* findOverride(std::span<const LayerOverride> overrides, std::size_t layer);

// Every override names an existing layer (once) and has valid settings; the message names it.
Status validateOverrides(std::span<const LayerOverride> overrides, std::size_t layerCount,
                         const ScheduleParameters& job);

} // namespace bladeaxis::scheduling

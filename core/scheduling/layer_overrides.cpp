#include "core/scheduling/layer_overrides.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace bladeaxis::scheduling {
namespace {

// The settings of a preset that act on one layer only (spec §2.5-§5).
void copyLayerSettings(const ScheduleParameters& from, ScheduleParameters& to) {
    to.preset = from.preset;
    to.marginRad = from.marginRad;
    to.allowNonmonotone = from.allowNonmonotone;
    to.leadMode = from.leadMode;
    to.leadFraction = from.leadFraction;
    to.leadSearchMinFraction = from.leadSearchMinFraction;
    to.leadSearchMaxFraction = from.leadSearchMaxFraction;
    to.leadSearchEvaluations = from.leadSearchEvaluations;
    to.keyMode = from.keyMode;
    to.keyToleranceRad = from.keyToleranceRad;
    to.adjust = from.adjust;
    to.epsilonRule = from.epsilonRule;
    to.cornerForm = from.cornerForm;
    to.finalClearanceRad = from.finalClearanceRad;
    to.epsilonBisectionSteps = from.epsilonBisectionSteps;
    to.curveChecksPerCubic = from.curveChecksPerCubic;
}

} // namespace

ScheduleParameters layerParameters(const ScheduleParameters& job, const LayerOverride& change) {
    ScheduleParameters parameters = job;
    if (change.preset) {
        copyLayerSettings(*change.preset == Preset::Faithful ? faithfulPreset() : bestPreset(),
                          parameters);
    }
    if (change.marginRad) {
        parameters.marginRad = *change.marginRad;
    }
    if (change.epsilonRule) {
        parameters.epsilonRule = *change.epsilonRule;
    }
    if (change.leadFraction) {
        parameters.leadMode = LeadMode::Fixed;
        parameters.leadFraction = *change.leadFraction;
    }
    return parameters;
}

const LayerOverride* findOverride(std::span<const LayerOverride> overrides, std::size_t layer) {
    const auto found = std::ranges::find(overrides, layer, &LayerOverride::layer);
    return found == overrides.end() ? nullptr : &*found;
}

Status validateOverrides(std::span<const LayerOverride> overrides, std::size_t layerCount,
                         const ScheduleParameters& job) {
    for (std::size_t i = 0; i < overrides.size(); ++i) {
        const LayerOverride& change = overrides[i];
        const std::string name = "layer " + std::to_string(change.layer);
        if (change.layer >= layerCount) {
            return makeError(ErrorCode::InvalidArgument,
                             "an edit names " + name + " but the toolpath has " +
                                 std::to_string(layerCount) + " layers");
        }
        if (findOverride(overrides.first(i), change.layer) != nullptr) {
            return makeError(ErrorCode::InvalidArgument, name + " is edited twice");
        }
        if (Status valid = validateParameters(layerParameters(job, change)); !valid) {
            return makeError(ErrorCode::InvalidArgument,
                             "the edit of " + name + ": " + valid.error().message);
        }
        const bool finite = std::ranges::all_of(change.keyPoints, [](const Vec2& point) {
            return std::isfinite(point.x()) && std::isfinite(point.y());
        });
        if (!finite || change.keyPoints.size() == 1) {
            return makeError(ErrorCode::InvalidArgument,
                             "the edit of " + name + " needs at least two finite key points");
        }
    }
    return {};
}

} // namespace bladeaxis::scheduling

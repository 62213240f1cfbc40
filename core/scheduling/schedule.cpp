#include "core/scheduling/schedule.h"

#include "core/base/free_storage.h"
#include "core/base/number_io.h"
#include "core/base/parallel.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"
#include "core/scheduling/channel.h"
#include "core/scheduling/curvature_states.h"
#include "core/scheduling/layer_edit.h"
#include "core/scheduling/layer_problem.h"
#include "core/scheduling/layer_scheduler.h"
#include "core/scheduling/layers.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/tangents.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace bladeaxis::scheduling {

bool isFlagged(const LayerResult& layer) {
    return std::ranges::any_of(layer.flags,
                               [](LayerStatus status) { return status != LayerStatus::Ok; });
}

std::vector<LayerBounds> layerBounds(const ScheduleResult& result) {
    std::vector<LayerBounds> bounds;
    bounds.reserve(result.layers.size());
    for (const LayerResult& layer : result.layers) {
        bounds.push_back({layer.first, layer.last});
    }
    return bounds;
}

void releaseLayerSamples(ScheduleResult& result) {
    for (LayerResult& layer : result.layers) {
        freeStorage(layer.inputIndex);
        for (std::vector<double>* curve :
             {&layer.thetaOriginal, &layer.thetaMin, &layer.thetaMax, &layer.lo, &layer.hi,
              &layer.theta, &layer.dTheta, &layer.ddTheta}) {
            freeStorage(*curve);
        }
    }
    result.layerSamplesReleased = true;
}

const char* toString(LayerStatus status) {
    switch (status) {
    case LayerStatus::Ok:
        return "ok";
    case LayerStatus::Pinched:
        return "pinched";
    case LayerStatus::MonotoneInfeasible:
        return "monotone infeasible";
    case LayerStatus::NoConcaveRun:
        return "no concave run";
    case LayerStatus::ShortLayer:
        return "short layer";
    case LayerStatus::NonMonotone:
        return "non-monotone";
    }
    return "unknown";
}

namespace {

// §6.5 asks for 1e-12 on the axis vectors; the angles of two layers that meet at a junction are
// computed from the same junction value, so anything above round-off is a real step.
constexpr double kJunctionGapRad = 1e-9;

CurvatureSettings curvatureSettings(const ScheduleParameters& p, const PlanePath& path,
                                    const TangentField& tangents, double radius) {
    // [A] "Layer length" in the §1.6 defaults is not known before the layers exist: the mean
    // arc length per revolution (total length / (total turning / 2 pi)) stands in for it.
    const double turning = tangents.forwardAngle.back() - tangents.forwardAngle.front();
    const double revolution =
        path.arcLength.back() * units::kTwoPi / std::max(std::abs(turning), units::kPi);
    CurvatureSettings settings;
    settings.windowMm =
        std::max(p.curvatureWindowMinMm, p.curvatureWindowRevolutionFraction * revolution);
    settings.hysteresisPerMm = p.curvatureHysteresisPerMm;
    settings.mergeGapMm = p.concaveGapToolRadii * radius;
    settings.minRunMm =
        std::max(p.concaveMinRunToolRadii * radius, p.concaveMinRunRevolutionFraction * revolution);
    return settings;
}

// The input records of each layer of a split: each layer's first and last sample's input.
std::vector<LayerBounds> boundsOf(const LayerSplit& split, const PlanePath& path) {
    std::vector<LayerBounds> bounds;
    bounds.reserve(split.layers.size());
    for (const LayerSpan& span : split.layers) {
        bounds.push_back({path.firstInput[span.first], path.firstInput[span.last]});
    }
    return bounds;
}

// The raw channel of the layers (§2), clipped as the parameters ask.
RawChannel channelOf(const LayerPlan& plan, const ScheduleParameters& p,
                     std::vector<std::string>& warnings) {
    RawChannel channel =
        buildRawChannel(plan.tangents, plan.curvature.runs, p.taperHalfAngleRad + p.safetyAngleRad);
    if (p.visibility == Visibility::Global) {
        const double turns = std::max(
            1.0, std::abs(plan.tangents.forwardAngle.back() - plan.tangents.forwardAngle.front()) /
                     units::kTwoPi);
        const auto reach = static_cast<std::size_t>(
            std::ceil(0.5 * static_cast<double>(plan.path.points.size()) / turns));
        clipGlobalVisibility(channel, plan.path.points, reach);
    }
    if (p.leadBand) {
        clipLeadBand(channel, plan.tangents, p.leadBandMinRad, p.leadBandMaxRad);
    }
    if (p.despike) {
        if (const std::size_t changed = despikeChannel(channel); changed > 0) {
            warnings.push_back("despiking changed " + std::to_string(changed) +
                               " channel samples (non-conservative)");
        }
    }
    return channel;
}

// Runs every layer; a parallel run writes each result into its own slot, so it is identical
// to the serial run.
std::vector<LayerOutcome> runLayers(std::vector<LayerProblem>& problems,
                                    std::span<const std::uint32_t> firstInput,
                                    std::span<const ScheduleParameters> layerParameters,
                                    const CancelToken* cancel) {
    std::vector<LayerOutcome> outcomes(problems.size());
    forEachItem(problems.size(), firstInput.size(), [&](std::size_t k) {
        if (isCancelled(cancel)) {
            return;
        }
        std::vector<std::size_t> inputs;
        inputs.reserve(problems[k].span.last - problems[k].span.first + 1);
        for (std::size_t i = problems[k].span.first; i <= problems[k].span.last; ++i) {
            inputs.push_back(firstInput[i]);
        }
        outcomes[k] =
            scheduleLayer(std::move(problems[k]), layerParameters[k], std::move(inputs), k);
    });
    return outcomes;
}

// Per layer: the job's parameters, or the layer's own when the engineer changed them.
std::vector<ScheduleParameters> parametersPerLayer(const ScheduleParameters& job,
                                                   std::span<const LayerOverride> overrides,
                                                   std::size_t layerCount) {
    std::vector<ScheduleParameters> perLayer(layerCount, job);
    for (const LayerOverride& change : overrides) {
        perLayer[change.layer] = layerParameters(job, change);
    }
    return perLayer;
}

// The engineer's key points replace the engine's polyline of their layer; a layer whose
// channel refuses them (moved ends, not monotone, outside the hull) fails the whole schedule,
// so a job never silently drops an edit.
Status applyKeyPointEdits(std::vector<LayerOutcome>& outcomes,
                          std::span<const LayerOverride> overrides,
                          std::span<const ScheduleParameters> perLayer) {
    for (const LayerOverride& change : overrides) {
        if (change.keyPoints.empty()) {
            continue;
        }
        LayerResult& layer = outcomes[change.layer].result;
        Result<LayerResult> edited = resmoothLayer(layer, change.keyPoints, perLayer[change.layer]);
        if (!edited) {
            return makeError(ErrorCode::InvalidArgument,
                             "the key points edited in layer " + std::to_string(change.layer) +
                                 " no longer fit its channel: " + edited.error().message);
        }
        edited->seconds = layer.seconds;
        layer = std::move(*edited);
    }
    return {};
}

bool keepsOriginal(const LayerResult& layer) {
    return std::find(layer.flags.begin(), layer.flags.end(), LayerStatus::MonotoneInfeasible) !=
           layer.flags.end();
}

// The inputs whose values come from layer k: from its first input up to the next layer's first
// input (a base point shared by two layers belongs to the later one), merged duplicates
// included. The layers' ranges are disjoint and cover every input.
struct InputRange {
    std::size_t begin = 0, end = 0;
};

InputRange inputsOfLayer(std::span<const LayerResult> layers, std::size_t k, std::size_t n) {
    return {layers[k].inputIndex.front(),
            k + 1 < layers.size() ? layers[k + 1].inputIndex.front() : n};
}

// An input of a MONOTONE_INFEASIBLE layer, which keeps its input orientation.
struct KeptAxis {
    std::size_t input = 0;
    Vec3 axis;
};

std::vector<KeptAxis> axesOfKeptLayers(std::span<const LayerResult> layers,
                                       const ScheduleSamples& input) {
    std::vector<KeptAxis> kept;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        if (!keepsOriginal(layers[k])) {
            continue;
        }
        const InputRange inputs = inputsOfLayer(layers, k, input.count());
        for (std::size_t i = inputs.begin; i < inputs.end; ++i) {
            kept.push_back({i, input.axes[i].normalized()});
        }
    }
    return kept;
}

// result.tiltB0 and result.traversalSign are the plane path's.
void assemble(ScheduleResult& result, const ScheduleSamples& input,
              std::vector<LayerOutcome>& outcomes) {
    const std::size_t n = input.count();
    result.layers.reserve(outcomes.size());
    for (LayerOutcome& outcome : outcomes) {
        result.warnings.insert(result.warnings.end(), outcome.warnings.begin(),
                               outcome.warnings.end());
        result.layers.push_back(std::move(outcome.result));
    }
    const std::vector<KeptAxis> kept = axesOfKeptLayers(result.layers, input);
    // The original angles are counted and dropped first: beside the new angles and axes they
    // would add 8 bytes per sample where read-schedule-write's memory peaks.
    result.originalReversals = countReversals(
        absoluteAngles(result.layers, n, Orientation::Original), tol::kReversalStepRad);
    const std::vector<double> thetaAbsolute =
        absoluteAngles(result.layers, n, Orientation::Rescheduled);
    ReconstructedPath rebuilt = reconstructAxes(thetaAbsolute, result.tiltB0, result.traversalSign);
    for (const KeptAxis& original : kept) {
        rebuilt.axes[original.input] = original.axis;
    }
    result.check = checkReconstruction(input, rebuilt, thetaAbsolute, result.tiltB0);
    result.newAxes = std::move(rebuilt.axes);
}

// §6.5 junction gap: where layer k ends and layer k+1 starts, in absolute angle. The shared
// base point is written once, so a gap shows as a step of the rotary axis next to it.
void checkJunctions(ScheduleResult& result) {
    for (std::size_t k = 0; k + 1 < result.layers.size(); ++k) {
        const LayerResult& before = result.layers[k];
        const LayerResult& after = result.layers[k + 1];
        if (before.theta.empty() || after.theta.empty()) {
            continue;
        }
        const double gap = std::abs((before.junctionAngle + before.theta.back()) -
                                    (after.junctionAngle + after.theta.front()));
        result.check.maxJunctionGapRad = std::max(result.check.maxJunctionGapRad, gap);
        if (gap > kJunctionGapRad) {
            result.warnings.push_back("the orientation steps by " +
                                      formatFixed(units::radToDeg(gap), 3) + " deg where layer " +
                                      std::to_string(k) + " meets layer " + std::to_string(k + 1) +
                                      " (input record " + std::to_string(after.first) + ")");
        }
    }
}

void addCheckWarnings(ScheduleResult& result) {
    if (!result.check.passes()) {
        result.warnings.push_back("reconstruction check failed: " + describeFailures(result.check));
    }
    if (result.check.reversals > 0) {
        result.warnings.push_back("the rotary axis reverses " +
                                  std::to_string(result.check.reversals) + " time(s)");
    }
    for (std::size_t k = 0; k < result.layers.size(); ++k) {
        if (result.layers[k].minClearance < -1e-9) {
            result.warnings.push_back(
                "layer " + std::to_string(k + 1) + " leaves the raw channel by " +
                formatFixed(units::radToDeg(-result.layers[k].minClearance), 4) + " deg");
        }
    }
}

} // namespace

std::vector<double> absoluteAngles(std::span<const LayerResult> layers, std::size_t inputs,
                                   Orientation which) {
    std::vector<double> angles(inputs);
    // Each layer writes its own input range, so the layers run at once.
    forEachItem(layers.size(), inputs, [&](std::size_t k) {
        const LayerResult& layer = layers[k];
        if (layer.inputIndex.empty()) {
            return;
        }
        const std::vector<double>& theta =
            which == Orientation::Original ? layer.thetaOriginal : layer.theta;
        const InputRange range = inputsOfLayer(layers, k, inputs);
        std::size_t j = 0; // the layer sample of input i: the last one whose input is <= i
        for (std::size_t i = range.begin; i < range.end; ++i) {
            while (j + 1 < layer.inputIndex.size() && layer.inputIndex[j + 1] <= i) {
                ++j;
            }
            angles[i] = layer.junctionAngle + theta[j];
        }
    });
    return angles;
}

namespace {

Status validateSamples(const ScheduleSamples& samples) {
    if (!std::isfinite(samples.toolRadius) || samples.toolRadius <= 0.0) {
        return makeError(ErrorCode::InvalidArgument,
                         "tool radius " + std::to_string(samples.toolRadius) + " mm is not > 0");
    }
    if (samples.points.size() != samples.axes.size()) {
        return makeError(ErrorCode::InvalidArgument, "centres and axes differ in length (" +
                                                         std::to_string(samples.points.size()) +
                                                         " vs " +
                                                         std::to_string(samples.axes.size()) + ")");
    }
    return {};
}

// The layer problems and their parameters, from the plan; what else the plan holds is freed
// before the problems are built, and the plan's arrays after: read-schedule-write's memory
// peaks here, and each per-point array freed is 8-24 bytes per point less beside the problems
// and then the layers' results.
struct LayerProblems {
    std::vector<LayerProblem> problems;
    std::vector<ScheduleParameters> perLayer;
    DefaultInitVector<std::uint32_t> firstInput; // of the plane path: the layers' inputs
};

Result<LayerProblems> layerProblemsOf(LayerPlan plan, const ScheduleSamples& samples,
                                      const ScheduleParameters& parameters,
                                      std::span<const LayerOverride> overrides,
                                      std::vector<std::string>& warnings) {
    const std::size_t layerCount = plan.split.layers.size();
    if (auto valid = validateOverrides(overrides, layerCount, parameters); !valid) {
        return std::unexpected(valid.error());
    }
    LayerProblems made;
    made.perLayer = parametersPerLayer(parameters, overrides, layerCount);
    std::vector<double> margins;
    margins.reserve(layerCount);
    for (const ScheduleParameters& layer : made.perLayer) {
        margins.push_back(layer.marginRad);
    }
    const RawChannel channel = channelOf(plan, parameters, warnings);
    const double shortLengthMm = 4.0 * plan.tangents.chordLengthMm;
    freeStorage(plan.tangents);
    freeStorage(plan.curvature);
    freeStorage(plan.path.points);
    addOriginalAngles(plan.path, samples.axes);
    made.problems = buildLayerProblems(plan.path, channel, plan.split, margins, shortLengthMm);
    for (const LayerProblem& problem : made.problems) {
        warnings.insert(warnings.end(), problem.warnings.begin(), problem.warnings.end());
    }
    made.firstInput = std::move(plan.path.firstInput);
    return made;
}

} // namespace

Result<PlanePath> makePlanePath(const ScheduleSamples& samples,
                                const ScheduleParameters& parameters) {
    if (auto status = validateParameters(parameters); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = validateSamples(samples); !status) {
        return std::unexpected(status.error());
    }
    return preparePlanePath(samples);
}

// Looks at the token after the tangents and after the curvature: at five million points each
// of this stage's steps takes 0.05-0.15 s.
Result<LayerPlan> planLayers(PlanePath path, const ScheduleSamples& samples,
                             const ScheduleParameters& p, const CancelToken* cancel) {
    auto tangents =
        computeWrappedTangents(path.points, p.tangentChordMinMm, p.tangentChordMedianFactor);
    if (!tangents) {
        return std::unexpected(tangents.error());
    }
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    LayerPlan plan;
    plan.path = std::move(path);
    plan.tangents = std::move(*tangents);
    // The unwrap and the curvature's prefix sums are each one chain through the path, whose
    // order fixes their rounding, and neither reads the other: on two threads they run at once.
    CurvatureWeights weights;
    runBoth(
        plan.path.points.size(), [&field = plan.tangents] { unwrapForwardAngles(field); },
        [&weights, &plan] {
            weights = curvatureWeights(plan.path.arcLength, plan.tangents.curvature);
        });
    const CurvatureSettings settings =
        curvatureSettings(p, plan.path, plan.tangents, samples.toolRadius);
    // Each per-point array goes once read for the last time: the channel is built where the
    // scheduling's memory peaks (beside the plane path). The curvature becomes the smoothed one.
    plan.curvature = analyseCurvature(plan.path.arcLength, std::move(plan.tangents.curvature),
                                      std::move(weights), plan.tangents.turning, settings);
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    plan.split = splitLayers(plan.tangents.forwardAngle, plan.curvature.smoothedCurvature,
                             plan.curvature.runs, p.basePoint);
    freeStorage(plan.curvature.smoothedCurvature); // the runs stay: the channel reads them
    freeStorage(plan.curvature.hysteresis);
    freeStorage(plan.curvature.state);
    plan.bounds = boundsOf(plan.split, plan.path);
    return plan;
}

Result<ScheduleResult> scheduleLayers(LayerPlan plan, const ScheduleSamples& samples,
                                      const ScheduleParameters& parameters,
                                      const CancelToken* cancel,
                                      std::span<const LayerOverride> overrides) {
    ScheduleResult result;
    result.warnings = std::move(plan.path.warnings);
    result.tiltB0 = plan.path.tiltB0;
    result.traversalSign = plan.path.traversalSign;
    for (std::size_t b : plan.split.basePoints) {
        result.basePoints.push_back(plan.path.firstInput[b]);
    }
    auto made = layerProblemsOf(std::move(plan), samples, parameters, overrides, result.warnings);
    if (!made) {
        return std::unexpected(made.error());
    }
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    std::vector<LayerOutcome> outcomes =
        runLayers(made->problems, made->firstInput, made->perLayer, cancel);
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    if (auto applied = applyKeyPointEdits(outcomes, overrides, made->perLayer); !applied) {
        return std::unexpected(applied.error());
    }
    // The layers have what they need of the plane path: its input index per point (8 bytes) is
    // not held beside the new axes.
    freeStorage(made->firstInput);
    assemble(result, samples, outcomes);
    checkJunctions(result);
    addCheckWarnings(result);
    return result;
}

Result<ScheduleResult> schedule(const ScheduleSamples& samples,
                                const ScheduleParameters& parameters, const CancelToken* cancel,
                                std::span<const LayerOverride> overrides) {
    auto path = makePlanePath(samples, parameters);
    if (!path) {
        return std::unexpected(path.error());
    }
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    auto plan = planLayers(std::move(*path), samples, parameters, cancel);
    if (!plan) {
        return std::unexpected(plan.error());
    }
    return scheduleLayers(std::move(*plan), samples, parameters, cancel, overrides);
}

Result<ScheduleResult> schedule(const ScheduleInput& input, const ScheduleParameters& parameters,
                                const CancelToken* cancel,
                                std::span<const LayerOverride> overrides) {
    if (input.axes.size() != input.centres.size()) {
        return makeError(ErrorCode::InvalidArgument, "centres and axes differ in length (" +
                                                         std::to_string(input.centres.size()) +
                                                         " vs " +
                                                         std::to_string(input.axes.size()) + ")");
    }
    return schedule(samplesOf(input), parameters, cancel, overrides);
}

} // namespace bladeaxis::scheduling

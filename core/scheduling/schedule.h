#pragma once
// The scheduling engine (spec §1-§6): re-schedules the tool orientation of a four-axis helical
// toolpath in the S-theta plane so that the rotary axis turns monotonically and smoothly inside
// the feasible channel, keeping every ball centre Q_i. Pure numerics on arrays, no I/O.
//
// Pipeline: preparePlanePath (§1.2-1.4) -> computeTangents (§1.5) -> analyseCurvature (§1.6)
// -> splitLayers (§1.7) -> buildRawChannel / monotoneHull (§2) -> buildLayerProblems (§3.1,
// §3.3) -> scheduleLayer per layer, in parallel (§3.4, §4, §5) -> reconstructAxes (§6).

#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/geometry/vec.h"
#include "core/scheduling/curvature_states.h"
#include "core/scheduling/layer_overrides.h"
#include "core/scheduling/layers.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/reconstruction.h"
#include "core/scheduling/schedule_parameters.h"
#include "core/scheduling/schedule_samples.h"
#include "core/scheduling/tangents.h"

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::scheduling {

// The input records of one layer, [first, last] (the end is shared with the next layer).
struct LayerBounds {
    std::size_t first = 0, last = 0;
};

// A toolpath's cutter centres and tool axes held in arrays (the comparison's baselines and the
// tests give them so).
struct ScheduleInput {
    std::vector<Vec3> centres; // Q_i ball centres in W (x = rotary axis), feed order, mm
    std::vector<Vec3> axes;    // V_i original tool axes in W (normalised on input)
    double toolRadius = 0.0;   // R, mm
};

// The samples of arrays the caller keeps while the scheduling runs.
inline ScheduleSamples samplesOf(const ScheduleInput& input) {
    return ScheduleSamples::ofCentres(input.centres, input.axes, input.toolRadius);
}

enum class LayerStatus {
    Ok,
    Pinched,            // the margin was reduced locally (§2.5)
    MonotoneInfeasible, // no monotone path in the channel: the original orientation is kept
    NoConcaveRun,       // a base point of the layer is a fallback (§1.7)
    ShortLayer,         // S_e < 4 l_t or < 4 samples: no lead segments, end slope not forced
    NonMonotone,        // no monotone path; allowNonmonotone: the original projected onto the
                        // raw channel and smoothed (the rotary axis may reverse), §2.5
};

const char* toString(LayerStatus status);

struct LayerResult {
    // Input-index range (inclusive); the end sample is shared with the next layer.
    std::size_t first = 0, last = 0;
    std::vector<std::size_t> inputIndex; // input index of every layer sample (duplicates merged)
    // Per layer sample, relative to the layer reference angle junctionAngle, rad; s in mm.
    std::vector<double> s, thetaOriginal, thetaMin, thetaMax, lo, hi;
    std::vector<Vec2> keyPoints, polyline; // (S, theta)
    struct Corner {
        double s = 0.0, epsilon = 0.0;
        enum class Bound { Geometry, Channel, None } limitedBy = Bound::None;
    };
    std::vector<Corner> corners;
    std::vector<double> theta, dTheta, ddTheta; // final theta(S), theta', theta'' (analytic)
    std::vector<LayerStatus> flags;
    double minClearance = 0.0;  // min over samples of the distance to the raw channel, rad
    double junctionAngle = 0.0; // absolute in-plane angle of theta = 0 (J_k for layers k >= 1)
    double leadFraction = 0.0;  // rho used (§3.4)
    double peakSecondDerivative = 0.0; // peak |theta''| of the smoothed curve, rad/mm^2
    double seconds = 0.0;              // wall time of the per-layer stage
};

// True when a layer carries a status other than Ok: a finding the engineer should review.
bool isFlagged(const LayerResult& layer);

struct ScheduleResult {
    std::vector<LayerResult> layers;
    // Per input sample. The new tips are not kept (24 bytes per sample): each keeps its input's
    // ball centre, so it is tipOfBall(centres[i], newAxes[i], R). A batch job frees them once
    // its new motion is analysed unless an output reads them (job::Retention::newToolAxes).
    std::vector<Vec3> newAxes;
    double tiltB0 = 0.0;                 // rad
    int traversalSign = 1;               // w . a of §1.3; the machine sigma = -traversalSign
    std::vector<std::size_t> basePoints; // input indices of the base points
    ReconstructionCheck check;           // §6.5 on the output
    std::size_t originalReversals = 0;   // A reversals of the input orientation (§6.4)
    std::vector<std::string> warnings;
    bool layerSamplesReleased = false; // see releaseLayerSamples
};

// Frees what every layer holds per sample but its arc lengths s (a layer's sample count and
// length): the input indices, the original and channel angles, the hull and the final theta with
// its derivatives, 72 bytes per input sample. For a caller that has read them for the last time
// (a batch job once it has checked the input's orientation against the channel): the new tool
// axes, key points, corners, flags and every per-layer figure stay, and layerSamplesReleased
// says so. Nothing that reads the curves (absoluteAngles, layers.csv, the comparison, the S-theta
// editor) may be given the result afterwards.
void releaseLayerSamples(ScheduleResult& result);

enum class Orientation { Rescheduled, Original };

// The absolute unwrapped in-plane angle of every one of `inputs` input samples, rad, of the new
// or the original orientation, made from the layers (a merged duplicate takes the angle of the
// sample it is merged into). The result does not keep them: 16 bytes per input sample that only
// the reconstruction, the reversal count and the baselines read.
std::vector<double> absoluteAngles(std::span<const LayerResult> layers, std::size_t inputs,
                                   Orientation which);

inline std::vector<double> absoluteAngles(const ScheduleResult& result, Orientation which) {
    return absoluteAngles(result.layers, result.newAxes.size(), which);
}

// The bounds of every layer of a result.
std::vector<LayerBounds> layerBounds(const ScheduleResult& result);

// The scheduling runs in three stages that take and return values, so that a caller can do
// its own work between them (a job takes the input's motion per layer once the layers are
// known, and frees what it no longer needs before the scheduling's memory peaks) and what a
// stage no longer needs goes with the value it was moved into.
//
// Stage 1 (§1.2-1.4): the plane path. Errors: InvalidArgument (parameters, radius, sizes),
// Geometry (NaN, degenerate path).
Result<PlanePath> makePlanePath(const ScheduleSamples& samples,
                                const ScheduleParameters& parameters);

// Stage 2 (§1.5-1.7): the tangents, the curvature and the split into layers, with the bounds
// every layer of the result will have.
struct LayerPlan {
    PlanePath path;
    TangentField tangents;
    CurvatureAnalysis curvature; // its runs; the per-point curves are freed once split
    LayerSplit split;
    std::vector<LayerBounds> bounds; // input records of each layer
};
Result<LayerPlan> planLayers(PlanePath path, const ScheduleSamples& samples,
                             const ScheduleParameters& parameters, const CancelToken* cancel);

// Stage 3 (§2-§6): the channel, every layer's schedule (in parallel) and the new tool axes.
// Infeasible layers are not errors: they keep the original orientation and are flagged
// MonotoneInfeasible with a warning. `overrides` change single layers (the engineer's edits);
// every other layer is scheduled exactly as without them. Errors: InvalidArgument (an override
// that does not fit the layers or a key-point edit the layer's channel refuses), Cancelled.
Result<ScheduleResult> scheduleLayers(LayerPlan plan, const ScheduleSamples& samples,
                                      const ScheduleParameters& parameters,
                                      const CancelToken* cancel,
                                      std::span<const LayerOverride> overrides = {});

// The three stages one after the other; the errors of each (Cancelled between them).
Result<ScheduleResult> schedule(const ScheduleSamples& samples,
                                const ScheduleParameters& parameters,
                                const CancelToken* cancel = nullptr,
                                std::span<const LayerOverride> overrides = {});
Result<ScheduleResult> schedule(const ScheduleInput& input, const ScheduleParameters& parameters,
                                const CancelToken* cancel = nullptr,
                                std::span<const LayerOverride> overrides = {});

} // namespace bladeaxis::scheduling

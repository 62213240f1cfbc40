#include "core/scheduling/layer_problem.h"

#include "core/base/parallel.h"
#include "core/base/units.h"
#include "core/scheduling/detail/fast_angles.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

namespace {

constexpr double kEndTolerance = 1e-9; // rad, as the key point tolerance of §4.3

struct AbsoluteLayer {
    std::vector<double> rawMin, rawMax, original;
    MonotoneHull hull;
};

AbsoluteLayer absoluteLayer(const PlanePath& path, const RawChannel& channel, const LayerSpan& span,
                            double margin) {
    AbsoluteLayer layer;
    const auto first = static_cast<long>(span.first);
    const auto end = static_cast<long>(span.last) + 1;
    layer.rawMin.assign(channel.thetaMin.begin() + first, channel.thetaMin.begin() + end);
    layer.rawMax.assign(channel.thetaMax.begin() + first, channel.thetaMax.begin() + end);
    layer.original.resize(layer.rawMin.size());
    double turns = 0.0; // the turn count changes rarely from one sample to the next
    for (std::size_t j = 0; j < layer.original.size(); ++j) {
        // The input axis on the channel's branch: nearest to the channel middle.
        layer.original[j] = detail::unwrapNearGuessed(
            path.originalAngle[span.first + j], 0.5 * (layer.rawMin[j] + layer.rawMax[j]), turns);
    }
    // Only LO, HI and the flags are used from here on.
    layer.hull = monotoneBounds(layer.rawMin, layer.rawMax, margin);
    return layer;
}

void addFlag(LayerProblem& problem, LayerStatus status) {
    if (std::find(problem.flags.begin(), problem.flags.end(), status) == problem.flags.end()) {
        problem.flags.push_back(status);
    }
}

void markInfeasible(LayerProblem& problem, std::size_t k, const std::string& why) {
    addFlag(problem, LayerStatus::MonotoneInfeasible);
    problem.warnings.push_back("layer " + std::to_string(k) + ": " + why +
                               "; the original orientation is kept");
}

// §2.5 / §3.1 / §4.6: why the end values cannot be joined monotonically inside the hull, or
// nullptr when they can.
const char* infeasibility(const MonotoneHull& h, double startAbs, double endAbs) {
    if (h.infeasible) {
        return "the monotone hull is empty even without margin (pinch)";
    }
    if (startAbs < h.lo.front() - kEndTolerance || startAbs > h.hi.front() + kEndTolerance) {
        return "the start orientation lies outside the hull";
    }
    if (endAbs < h.lo.back() - kEndTolerance || endAbs > h.hi.back() + kEndTolerance) {
        return "the end orientation lies outside the hull";
    }
    if (endAbs - startAbs < -kEndTolerance || endAbs - startAbs > 2.0 * units::kTwoPi) {
        return "inconsistent base points (theta_e outside [0, 4 pi])";
    }
    return nullptr;
}

// [A] The shortest lead-out, as a fraction of the layer length: the smallest lead fraction the
// automatic search of §3.4 tries.
constexpr double kShortestLeadFraction = 0.02;

// §3.1 puts J_k at the top of the hull at the base point. After a concave run the hull is flat
// there (the concave rule holds theta_max at the exit's forward limit), so a horizontal
// lead-out at J_k fits. At a fallback base point (no concave run) HI still rises up to the base
// point, and a horizontal lead-out at HI(end) would leave the hull at once: the layer could
// only end with a one-sample lead, outside the margin, and the zero end slope of §3.2 would
// have no room. So J_k is never above HI where the shortest lead-out starts (HI is
// non-decreasing, so that is HI's least value over the lead-out).
double hullTopBeforeLeadOut(const PlanePath& path, const LayerSpan& span,
                            const AbsoluteLayer& layer) {
    const double start = path.arcLength[span.first];
    const double length = path.arcLength[span.last] - start;
    const double leadOutStart = start + (1.0 - kShortestLeadFraction) * length;
    std::size_t j = layer.hull.hi.size() - 1;
    while (j > 0 && path.arcLength[span.first + j] > leadOutStart) {
        --j;
    }
    return layer.hull.hi[j];
}

struct LayerEnds {
    double startAbs = 0.0, endAbs = 0.0;
};

// §3.1 junction values, or §3.3 free ends: the input orientation clamped into the hull, keeping
// theta monotone.
LayerEnds endsOf(const AbsoluteLayer& a, const LayerSpan& span, double startJunction,
                 double endJunction) {
    const MonotoneHull& h = a.hull;
    LayerEnds ends;
    ends.startAbs = span.startFree ? std::clamp(a.original.front(), h.lo.front(),
                                                std::max(h.lo.front(), h.hi.front()))
                                   : startJunction;
    ends.endAbs = span.endFree ? std::clamp(a.original.back(), std::max(h.lo.back(), ends.startAbs),
                                            std::max({h.hi.back(), h.lo.back(), ends.startAbs}))
                               : endJunction;
    return ends;
}

// [A] A layer that keeps its original orientation (MONOTONE_INFEASIBLE) does not end at the
// junction angles its neighbours were given, so joining them there would make the rotary axis
// jump at both base points. Its neighbours' shared ends become free ends instead (§3.3): they
// meet the kept original orientation itself, clamped into their hull, and the junction stays
// continuous whenever the original lies inside it. One pass suffices: freeing an end only
// clamps it into its own hull, so no further layer becomes infeasible.
std::vector<LayerSpan> spansAroundKeptLayers(const LayerSplit& split,
                                             std::span<const AbsoluteLayer> absolute,
                                             std::span<const double> junction,
                                             std::vector<std::string>& warnings) {
    std::vector<LayerSpan> spans = split.layers;
    const std::size_t count = spans.size();
    std::vector<bool> kept(count, false);
    for (std::size_t k = 0; k < count; ++k) {
        const LayerEnds ends = endsOf(absolute[k], spans[k], junction[k], junction[k + 1]);
        kept[k] = infeasibility(absolute[k].hull, ends.startAbs, ends.endAbs) != nullptr;
    }
    for (std::size_t k = 0; k < count; ++k) {
        if (!kept[k]) {
            continue;
        }
        if (k > 0 && !kept[k - 1] && !spans[k - 1].endFree) {
            spans[k - 1].endFree = true;
            warnings.push_back("layer " + std::to_string(k - 1) +
                               " ends at the original orientation of the kept layer " +
                               std::to_string(k));
        }
        if (k + 1 < count && !kept[k + 1] && !spans[k + 1].startFree) {
            spans[k + 1].startFree = true;
            warnings.push_back("layer " + std::to_string(k + 1) +
                               " starts at the original orientation of the kept layer " +
                               std::to_string(k));
        }
    }
    return spans;
}

// Layer k's problem: its ends, its flags, and its channel relative to its start value.
LayerProblem layerProblem(const PlanePath& path, const LayerSpan& span, AbsoluteLayer& a,
                          double startJunction, double endJunction, double shortLengthMm,
                          std::size_t k) {
    LayerProblem p;
    p.span = span;
    const MonotoneHull& h = a.hull;
    const LayerEnds ends = endsOf(a, p.span, startJunction, endJunction);
    const double startAbs = ends.startAbs;
    const double endAbs = ends.endAbs;
    p.reference = startAbs;
    p.startValue = 0.0;
    p.endValue = endAbs - startAbs;
    p.s.resize(a.rawMin.size());
    for (std::size_t i = 0; i < p.s.size(); ++i) {
        p.s[i] = path.arcLength[p.span.first + i] - path.arcLength[p.span.first];
    }
    p.shortLayer = p.s.size() < 4 || p.s.back() < shortLengthMm;
    if (h.pinched) {
        addFlag(p, LayerStatus::Pinched);
    }
    if (p.span.fallbackBase) {
        addFlag(p, LayerStatus::NoConcaveRun);
    }
    if (p.shortLayer) {
        addFlag(p, LayerStatus::ShortLayer);
    }
    if (const char* why = infeasibility(h, startAbs, endAbs)) {
        markInfeasible(p, k, why);
    }
    // The absolute vectors move into the problem and become relative in place.
    const auto shifted = [startAbs](std::vector<double>& values) {
        for (double& v : values) {
            v -= startAbs;
        }
        return std::move(values);
    };
    p.rawMin = shifted(a.rawMin);
    p.rawMax = shifted(a.rawMax);
    p.lo = shifted(a.hull.lo);
    p.hi = shifted(a.hull.hi);
    p.original = shifted(a.original);
    return p;
}

} // namespace

std::vector<LayerProblem> buildLayerProblems(const PlanePath& path, const RawChannel& channel,
                                             const LayerSplit& split,
                                             std::span<const double> margins,
                                             double shortLengthMm) {
    const std::size_t count = split.layers.size();
    const std::size_t points = path.arcLength.size();
    std::vector<AbsoluteLayer> absolute(count);
    forEachItem(count, points, [&](std::size_t k) {
        absolute[k] = absoluteLayer(path, channel, split.layers[k], margins[k]);
    });
    // J_k for k >= 1: the base vector on layer k's hull, never above layer k-1's hull over its
    // shortest lead-out [A].
    std::vector<double> junction(count + 1, 0.0);
    for (std::size_t k = 1; k < count; ++k) {
        junction[k] = std::min(absolute[k].hull.hi.front(),
                               hullTopBeforeLeadOut(path, split.layers[k - 1], absolute[k - 1]));
    }
    std::vector<std::string> junctionWarnings;
    const std::vector<LayerSpan> spans =
        spansAroundKeptLayers(split, absolute, junction, junctionWarnings);
    std::vector<LayerProblem> problems(count);
    forEachItem(count, points, [&](std::size_t k) {
        problems[k] = layerProblem(path, spans[k], absolute[k], junction[k], junction[k + 1],
                                   shortLengthMm, k);
    });
    if (!problems.empty()) {
        problems.front().warnings.insert(problems.front().warnings.begin(),
                                         junctionWarnings.begin(), junctionWarnings.end());
    }
    return problems;
}

} // namespace bladeaxis::scheduling

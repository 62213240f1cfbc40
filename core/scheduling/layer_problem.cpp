#include "core/scheduling/layer_problem.h"

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
    for (std::size_t j = 0; j < layer.original.size(); ++j) {
        // The input axis on the channel's branch: nearest to the channel middle.
        layer.original[j] = detail::unwrapNear(path.originalAngle[span.first + j],
                                               0.5 * (layer.rawMin[j] + layer.rawMax[j]));
    }
    layer.hull = monotoneHull(layer.rawMin, layer.rawMax, margin);
    // Only LO, HI and the flags are used from here on: release the rest now, so that the next
    // layer reuses the memory (fresh pages are the main cost of large paths).
    layer.hull.lo0 = {};
    layer.hull.hi0 = {};
    layer.hull.marginLo = {};
    layer.hull.marginHi = {};
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

// §2.5 / §3.1 / §4.6 checks of the end values against the hull.
void checkEnds(LayerProblem& p, const AbsoluteLayer& a, double startAbs, double endAbs,
               std::size_t k) {
    const MonotoneHull& h = a.hull;
    if (h.infeasible) {
        markInfeasible(p, k, "the monotone hull is empty even without margin (pinch)");
    } else if (startAbs < h.lo.front() - kEndTolerance || startAbs > h.hi.front() + kEndTolerance) {
        markInfeasible(p, k, "the start orientation lies outside the hull");
    } else if (endAbs < h.lo.back() - kEndTolerance || endAbs > h.hi.back() + kEndTolerance) {
        markInfeasible(p, k, "the end orientation lies outside the hull");
    } else if (endAbs - startAbs < -kEndTolerance || endAbs - startAbs > 2.0 * units::kTwoPi) {
        markInfeasible(p, k, "inconsistent base points (theta_e outside [0, 4 pi])");
    }
}

} // namespace

std::vector<LayerProblem> buildLayerProblems(const PlanePath& path, const RawChannel& channel,
                                             const LayerSplit& split,
                                             std::span<const double> margins,
                                             double shortLengthMm) {
    const std::size_t count = split.layers.size();
    std::vector<AbsoluteLayer> absolute;
    absolute.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        absolute.push_back(absoluteLayer(path, channel, split.layers[k], margins[k]));
    }
    // J_k for k >= 1: the base vector on layer k's hull, never above layer k-1's end hull [A].
    std::vector<double> junction(count + 1, 0.0);
    for (std::size_t k = 1; k < count; ++k) {
        junction[k] = std::min(absolute[k].hull.hi.front(), absolute[k - 1].hull.hi.back());
    }
    std::vector<LayerProblem> problems(count);
    for (std::size_t k = 0; k < count; ++k) {
        LayerProblem& p = problems[k];
        AbsoluteLayer& a = absolute[k];
        p.span = split.layers[k];
        const MonotoneHull& h = a.hull;
        // §3.3 free ends: clamp the input orientation into the hull, keeping theta monotone.
        const double startAbs = p.span.startFree ? std::clamp(a.original.front(), h.lo.front(),
                                                              std::max(h.lo.front(), h.hi.front()))
                                                 : junction[k];
        const double endAbs = p.span.endFree
                                  ? std::clamp(a.original.back(), std::max(h.lo.back(), startAbs),
                                               std::max({h.hi.back(), h.lo.back(), startAbs}))
                                  : junction[k + 1];
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
        checkEnds(p, a, startAbs, endAbs, k);
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
    }
    return problems;
}

} // namespace bladeaxis::scheduling

#include "core/scheduling/layers.h"

#include "core/base/units.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace bladeaxis::scheduling {

namespace {

using units::kPi;
using units::kTwoPi;

struct Candidate {
    std::size_t index;
    double lengthMm;
    double absTurningRad;
};

bool better(const Candidate& a, const Candidate& b) {
    if (a.lengthMm != b.lengthMm) {
        return a.lengthMm > b.lengthMm; // main run: the longest, ties by the larger |turning|
    }
    return a.absTurningRad > b.absTurningRad;
}

// better(), and of two equally good candidates the first along the path.
bool preferred(const Candidate& a, const Candidate& b) {
    return better(a, b) || (!better(b, a) && a.index < b.index);
}

std::vector<Candidate> candidatesOf(std::span<const ConcaveRun> runs, std::size_t n,
                                    BasePointRule rule) {
    std::vector<Candidate> candidates;
    for (const ConcaveRun& run : runs) {
        const std::size_t index = rule == BasePointRule::Exit ? run.exit : run.entry;
        if (index > 0 && index + 1 < n) { // an altered point strictly inside the path
            candidates.push_back({index, run.lengthMm, run.absTurningRad});
        }
    }
    return candidates;
}

struct Walker {
    Walker(std::span<const double> phi_, std::span<const double> kappa_,
           std::vector<Candidate> candidates_)
        : phi(phi_), kappa(kappa_), candidates(std::move(candidates_)) {
        // By turning angle, so that a window of angles is found by binary search instead of
        // a scan of every candidate (the walk asks once per layer: quadratic in the layers).
        std::sort(candidates.begin(), candidates.end(),
                  [this](const Candidate& a, const Candidate& b) {
                      return phi[a.index] != phi[b.index] ? phi[a.index] < phi[b.index]
                                                          : a.index < b.index;
                  });
    }

    std::span<const double> phi;
    std::span<const double> kappa;
    std::vector<Candidate> candidates; // by phi, then by index

    // Best candidate with phi in [low, high); of equals, the first along the path.
    std::optional<std::size_t> bestIn(double low, double high) const {
        const auto first =
            std::partition_point(candidates.begin(), candidates.end(),
                                 [&](const Candidate& c) { return phi[c.index] < low; });
        std::optional<Candidate> best;
        for (auto c = first; c != candidates.end() && phi[c->index] < high; ++c) {
            if (!best || preferred(*c, *best)) {
                best = *c;
            }
        }
        return best ? std::optional(best->index) : std::nullopt;
    }

    // Fallback: the flattest sample within +-pi/2 of the target turning angle [A].
    std::optional<std::size_t> flattestNear(double target) const {
        std::optional<std::size_t> best;
        for (std::size_t i = 1; i + 1 < phi.size(); ++i) {
            if (std::abs(phi[i] - target) <= 0.5 * kPi &&
                (!best || std::abs(kappa[i]) < std::abs(kappa[*best]))) {
                best = i;
            }
        }
        return best;
    }
};

// Walks one direction from the anchor: the next base point lies in [phi + pi, phi + 3 pi)
// (direction +1) or (phi - 3 pi, phi - pi] (direction -1), spec §1.7 pseudo-code.
void walk(const Walker& w, std::size_t anchor, int direction,
          std::vector<std::pair<std::size_t, bool>>& found) {
    double phiPrev = w.phi[anchor];
    const double phiStart = w.phi.front();
    const double phiEnd = w.phi.back();
    while (true) {
        const double target = phiPrev + direction * kTwoPi;
        std::optional<std::size_t> next =
            direction > 0 ? w.bestIn(phiPrev + kPi, phiPrev + 3.0 * kPi)
                          : w.bestIn(std::nextafter(phiPrev - 3.0 * kPi, phiEnd),
                                     std::nextafter(phiPrev - kPi, phiEnd));
        bool fallback = false;
        if (!next && target > phiStart && target < phiEnd) {
            next = w.flattestNear(target);
            fallback = true;
        }
        if (!next) {
            return;
        }
        found.emplace_back(*next, fallback);
        phiPrev = w.phi[*next];
    }
}

std::optional<std::size_t> anchorOf(const Walker& w, bool& fallback) {
    fallback = false;
    if (!w.candidates.empty()) {
        return std::min_element(w.candidates.begin(), w.candidates.end(), preferred)->index;
    }
    // No concave run anywhere: a fallback anchor only if the path makes a whole revolution.
    if (w.phi.back() - w.phi.front() < kTwoPi) {
        return std::nullopt;
    }
    fallback = true;
    return w.flattestNear(w.phi.front() + kPi);
}

} // namespace

LayerSplit splitLayers(std::span<const double> forwardAngle,
                       std::span<const double> smoothedCurvature, std::span<const ConcaveRun> runs,
                       BasePointRule rule) {
    const std::size_t n = forwardAngle.size();
    LayerSplit split;
    if (n < 2) {
        return split;
    }
    const Walker walker(forwardAngle, smoothedCurvature, candidatesOf(runs, n, rule));
    bool anchorFallback = false;
    if (std::optional<std::size_t> anchor = anchorOf(walker, anchorFallback)) {
        std::vector<std::pair<std::size_t, bool>> found{{*anchor, anchorFallback}};
        walk(walker, *anchor, +1, found);
        walk(walker, *anchor, -1, found);
        std::sort(found.begin(), found.end());
        for (const auto& [index, fallback] : found) {
            if (index > 0 && index + 1 < n &&
                (split.basePoints.empty() || index > split.basePoints.back())) {
                split.basePoints.push_back(index);
                split.fallback.push_back(fallback);
            }
        }
    }
    std::size_t start = 0;
    for (std::size_t k = 0; k <= split.basePoints.size(); ++k) {
        LayerSpan span;
        span.first = start;
        span.last = k < split.basePoints.size() ? split.basePoints[k] : n - 1;
        span.startFree = k == 0;
        span.endFree = k == split.basePoints.size();
        span.fallbackBase =
            (k > 0 && split.fallback[k - 1]) || (k < split.basePoints.size() && split.fallback[k]);
        split.layers.push_back(span);
        start = span.last;
    }
    return split;
}

} // namespace bladeaxis::scheduling

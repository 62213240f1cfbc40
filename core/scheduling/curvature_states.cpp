#include "core/scheduling/curvature_states.h"

#include "core/base/parallel.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace bladeaxis::scheduling {

namespace {

// kappa-bar_i: arc-length weighted mean of the per-sample curvature over |S_k - S_i| <= w/2
// (two pointers over prefix sums, O(n)). The window of sample i is [low(i), high(i)), low the
// first sample within w/2 before i and high the first beyond w/2 after it; both only grow with
// i, so a range of samples finds its first window by binary search and walks from there, as
// the serial walk from sample 0 would.
// The smoothed values are written over kappa's own: only the prefix sums read it.
DefaultInitVector<double> smoothCurvature(std::span<const double> s,
                                          DefaultInitVector<double> kappa,
                                          const CurvatureWeights prefix, double window) {
    const std::size_t n = s.size();
    DefaultInitVector<double> smoothed = std::move(kappa);
    const double half = 0.5 * window;
    forEachRange(n, [&](std::size_t begin, std::size_t end) {
        const auto indexOf = [&s](auto it) { return static_cast<std::size_t>(it - s.begin()); };
        std::size_t low =
            indexOf(std::partition_point(s.begin(), s.begin() + static_cast<long>(begin),
                                         [&](double sl) { return s[begin] - sl > half; }));
        std::size_t high = indexOf(std::partition_point(
            s.begin(), s.end(), [&](double sh) { return sh - s[begin] <= half; }));
        for (std::size_t i = begin; i < end; ++i) {
            while (s[i] - s[low] > half) {
                ++low;
            }
            while (high < n && s[high] - s[i] <= half) {
                ++high;
            }
            smoothed[i] = (prefix.weighted[high] - prefix.weighted[low]) /
                          (prefix.weight[high] - prefix.weight[low]);
        }
    });
    return smoothed;
}

// Hysteresis: switch only beyond +-kappa_h. [A] Before the first decisive sample the state is
// back-filled with the first decided state (the paper does not say where the path starts).
// A sample's state is that of the last decisive sample up to it, so ranges of samples are
// decided at once from their own first decisive sample on; the samples before it take the
// state the ranges before ended in, filled in afterwards.
struct HysteresisRange {
    std::size_t end = 0;
    std::size_t firstDecisive = 0;                // == end: no decisive sample in the range
    CurvatureState last = CurvatureState::Convex; // the state at the range's end, if decided
    bool decides() const { return firstDecisive < end; }
};

DefaultInitVector<CurvatureState> hysteresisStates(std::span<const double> smoothed,
                                                   double threshold) {
    const std::size_t n = smoothed.size();
    DefaultInitVector<CurvatureState> states(n); // every sample is written below
    std::vector<HysteresisRange> ranges(rangeCount(n));
    CurvatureState* const out = states.data();
    forEachRangeOf(
        n, ranges.size(),
        [&ranges, smoothed, threshold, out](std::size_t r, std::size_t begin, std::size_t end) {
            std::size_t firstDecisive = end;
            CurvatureState current = CurvatureState::Convex;
            for (std::size_t i = begin; i < end; ++i) {
                if (smoothed[i] > threshold || smoothed[i] < -threshold) {
                    current = smoothed[i] > 0.0 ? CurvatureState::Convex : CurvatureState::Concave;
                    firstDecisive = std::min(firstDecisive, i);
                }
                out[i] = current; // before firstDecisive: replaced below
            }
            ranges[r] = {end, firstDecisive, current};
        });
    // The state each range's undecided start takes: up to the path's first decisive sample the
    // state that sample decides (Convex when there is none), then the state the last deciding
    // range ended in.
    const auto firstDeciding = std::find_if(ranges.begin(), ranges.end(),
                                            [](const HysteresisRange& r) { return r.decides(); });
    CurvatureState state =
        firstDeciding != ranges.end() ? out[firstDeciding->firstDecisive] : CurvatureState::Convex;
    std::vector<CurvatureState> incoming(ranges.size());
    for (std::size_t r = 0; r < ranges.size(); ++r) {
        incoming[r] = state;
        state = ranges[r].decides() ? ranges[r].last : state;
    }
    forEachRangeOf(n, ranges.size(), [&](std::size_t r, std::size_t begin, std::size_t) {
        std::fill(out + begin, out + ranges[r].firstDecisive, incoming[r]);
    });
    return states;
}

// The runs start where a concave state follows a convex one (or the path starts concave) and
// end where a convex one follows: they are made from the altered points, in order (a few per
// layer).
std::vector<ConcaveRun> runsOf(std::span<const CurvatureState> states) {
    const std::size_t n = states.size();
    std::vector<ConcaveRun> runs;
    if (n > 0 && states[0] == CurvatureState::Concave) {
        runs.push_back({0, n, 0.0, 0.0});
    }
    for (std::size_t i : alteredPoints(states)) {
        if (states[i] == CurvatureState::Concave) {
            runs.push_back({i, n, 0.0, 0.0});
        } else {
            runs.back().exit = i; // a change to convex follows a concave run
        }
    }
    return runs;
}

double endArc(std::span<const double> s, const ConcaveRun& run) {
    return run.exit < s.size() ? s[run.exit] : s.back();
}

std::vector<ConcaveRun> mergeAndDrop(std::vector<ConcaveRun> runs, std::span<const double> s,
                                     std::span<const double> turning,
                                     const CurvatureSettings& settings) {
    std::vector<ConcaveRun> merged;
    for (const ConcaveRun& run : runs) {
        if (!merged.empty() && merged.back().exit < s.size() &&
            s[run.entry] - s[merged.back().exit] < settings.mergeGapMm) {
            merged.back().exit = run.exit; // short convex gap: one run
        } else {
            merged.push_back(run);
        }
    }
    // Each run's sum in order, the runs at once.
    forEachItem(merged.size(), s.size(), [&merged, s, turning](std::size_t r) {
        ConcaveRun& run = merged[r];
        run.lengthMm = endArc(s, run) - s[run.entry];
        const std::size_t stop = std::min(run.exit, s.size());
        double sum = 0.0;
        for (std::size_t k = run.entry; k < stop; ++k) {
            sum += std::abs(turning[k]);
        }
        run.absTurningRad = sum;
    });
    std::vector<ConcaveRun> kept;
    std::copy_if(merged.begin(), merged.end(), std::back_inserter(kept),
                 [&settings](const ConcaveRun& run) { return run.lengthMm >= settings.minRunMm; });
    return kept;
}

} // namespace

CurvatureWeights curvatureWeights(std::span<const double> s, std::span<const double> kappa) {
    const std::size_t n = s.size();
    CurvatureWeights prefix;
    prefix.weighted.resize(n + 1);
    prefix.weight.resize(n + 1);
    prefix.weighted[0] = 0.0;
    prefix.weight[0] = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double left = k > 0 ? s[k] - s[k - 1] : 0.0;
        const double right = k + 1 < n ? s[k + 1] - s[k] : 0.0;
        const double weight = std::max(0.5 * (left + right), 1e-12);
        prefix.weighted[k + 1] = prefix.weighted[k] + kappa[k] * weight;
        prefix.weight[k + 1] = prefix.weight[k] + weight;
    }
    return prefix;
}

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   std::span<const double> curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings) {
    return analyseCurvature(arcLength,
                            DefaultInitVector<double>(curvature.begin(), curvature.end()), turning,
                            settings);
}

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings) {
    CurvatureWeights weights = curvatureWeights(arcLength, curvature);
    return analyseCurvature(arcLength, std::move(curvature), std::move(weights), turning, settings);
}

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   CurvatureWeights&& weights, std::span<const double> turning,
                                   const CurvatureSettings& settings) {
    CurvatureAnalysis analysis;
    if (arcLength.empty()) {
        return analysis;
    }
    analysis.smoothedCurvature =
        smoothCurvature(arcLength, std::move(curvature), std::move(weights), settings.windowMm);
    analysis.hysteresis = hysteresisStates(analysis.smoothedCurvature, settings.hysteresisPerMm);
    analysis.runs = mergeAndDrop(runsOf(analysis.hysteresis), arcLength, turning, settings);
    analysis.state.assign(arcLength.size(), CurvatureState::Convex);
    for (const ConcaveRun& run : analysis.runs) {
        for (std::size_t k = run.entry; k < std::min(run.exit, arcLength.size()); ++k) {
            analysis.state[k] = CurvatureState::Concave;
        }
    }
    return analysis;
}

std::vector<std::size_t> alteredPoints(std::span<const CurvatureState> states) {
    // Each range of samples lists its own changes; the lists are joined in order.
    const std::size_t n = states.size();
    std::vector<std::vector<std::size_t>> changes(rangeCount(n));
    forEachRangeOf(n, changes.size(),
                   [&changes, states](std::size_t r, std::size_t begin, std::size_t end) {
                       for (std::size_t i = std::max<std::size_t>(begin, 1); i < end; ++i) {
                           if (states[i] != states[i - 1]) {
                               changes[r].push_back(i);
                           }
                       }
                   });
    std::vector<std::size_t> points;
    for (const std::vector<std::size_t>& rangeChanges : changes) {
        points.insert(points.end(), rangeChanges.begin(), rangeChanges.end());
    }
    return points;
}

} // namespace bladeaxis::scheduling

#include "core/scheduling/curvature_states.h"

#include "core/base/parallel.h"

#include <algorithm>
#include <cmath>

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
                                          const CurvatureWeights prefix, double window,
                                          unsigned threads) {
    const std::size_t n = s.size();
    DefaultInitVector<double> smoothed = std::move(kappa);
    const double half = 0.5 * window;
    forEachRange(n, threads, [&](std::size_t begin, std::size_t end) {
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
DefaultInitVector<CurvatureState> hysteresisStates(std::span<const double> smoothed,
                                                   double threshold) {
    DefaultInitVector<CurvatureState> states(smoothed.size()); // every sample is written below
    bool decided = false;
    CurvatureState current = CurvatureState::Convex;
    std::size_t undecided = 0;
    for (std::size_t i = 0; i < smoothed.size(); ++i) {
        if (smoothed[i] > threshold || smoothed[i] < -threshold) {
            current = smoothed[i] > 0.0 ? CurvatureState::Convex : CurvatureState::Concave;
            if (!decided) {
                for (std::size_t k = 0; k < undecided; ++k) {
                    states[k] = current;
                }
                decided = true;
            }
        } else if (!decided) {
            ++undecided;
        }
        states[i] = current;
    }
    return states;
}

std::vector<ConcaveRun> runsOf(std::span<const CurvatureState> states) {
    std::vector<ConcaveRun> runs;
    for (std::size_t i = 0; i < states.size(); ++i) {
        const bool concave = states[i] == CurvatureState::Concave;
        const bool starts = concave && (i == 0 || states[i - 1] != CurvatureState::Concave);
        if (starts) {
            runs.push_back({i, states.size(), 0.0, 0.0});
        }
        if (!concave && !runs.empty() && runs.back().exit == states.size() && i > 0 &&
            states[i - 1] == CurvatureState::Concave) {
            runs.back().exit = i;
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
    std::vector<ConcaveRun> kept;
    for (ConcaveRun run : merged) {
        run.lengthMm = endArc(s, run) - s[run.entry];
        const std::size_t stop = std::min(run.exit, s.size());
        for (std::size_t k = run.entry; k < stop; ++k) {
            run.absTurningRad += std::abs(turning[k]);
        }
        if (run.lengthMm >= settings.minRunMm) {
            kept.push_back(run);
        }
    }
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
                                   const CurvatureSettings& settings, unsigned threads) {
    return analyseCurvature(arcLength,
                            DefaultInitVector<double>(curvature.begin(), curvature.end()), turning,
                            settings, threads);
}

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings, unsigned threads) {
    CurvatureWeights weights = curvatureWeights(arcLength, curvature);
    return analyseCurvature(arcLength, std::move(curvature), std::move(weights), turning, settings,
                            threads);
}

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   DefaultInitVector<double>&& curvature,
                                   CurvatureWeights&& weights, std::span<const double> turning,
                                   const CurvatureSettings& settings, unsigned threads) {
    CurvatureAnalysis analysis;
    if (arcLength.empty()) {
        return analysis;
    }
    analysis.smoothedCurvature = smoothCurvature(arcLength, std::move(curvature),
                                                 std::move(weights), settings.windowMm, threads);
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
    std::vector<std::size_t> points;
    for (std::size_t i = 1; i < states.size(); ++i) {
        if (states[i] != states[i - 1]) {
            points.push_back(i);
        }
    }
    return points;
}

} // namespace bladeaxis::scheduling

#include "core/scheduling/curvature_states.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

namespace {

// kappa-bar_i: arc-length weighted mean of the per-sample curvature over |S_k - S_i| <= w/2
// (two pointers over prefix sums, O(n)).
std::vector<double> smoothCurvature(std::span<const double> s, std::span<const double> kappa,
                                    double window) {
    const std::size_t n = s.size();
    std::vector<double> weightedPrefix(n + 1, 0.0);
    std::vector<double> weightPrefix(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double left = k > 0 ? s[k] - s[k - 1] : 0.0;
        const double right = k + 1 < n ? s[k + 1] - s[k] : 0.0;
        const double weight = std::max(0.5 * (left + right), 1e-12);
        weightedPrefix[k + 1] = weightedPrefix[k] + kappa[k] * weight;
        weightPrefix[k + 1] = weightPrefix[k] + weight;
    }
    std::vector<double> smoothed(n);
    std::size_t low = 0;
    std::size_t high = 0; // window = [low, high)
    for (std::size_t i = 0; i < n; ++i) {
        while (s[i] - s[low] > 0.5 * window) {
            ++low;
        }
        while (high < n && s[high] - s[i] <= 0.5 * window) {
            ++high;
        }
        smoothed[i] =
            (weightedPrefix[high] - weightedPrefix[low]) / (weightPrefix[high] - weightPrefix[low]);
    }
    return smoothed;
}

// Hysteresis: switch only beyond +-kappa_h. [A] Before the first decisive sample the state is
// back-filled with the first decided state (the paper does not say where the path starts).
std::vector<CurvatureState> hysteresisStates(std::span<const double> smoothed, double threshold) {
    std::vector<CurvatureState> states(smoothed.size(), CurvatureState::Convex);
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

CurvatureAnalysis analyseCurvature(std::span<const double> arcLength,
                                   std::span<const double> curvature,
                                   std::span<const double> turning,
                                   const CurvatureSettings& settings) {
    CurvatureAnalysis analysis;
    if (arcLength.empty()) {
        return analysis;
    }
    analysis.smoothedCurvature = smoothCurvature(arcLength, curvature, settings.windowMm);
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

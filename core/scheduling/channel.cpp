#include "core/scheduling/channel.h"

#include "core/base/parallel.h"
#include "core/base/units.h"
#include "core/geometry/angles.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bladeaxis::scheduling {

RawChannel buildRawChannel(const TangentField& tangents, std::span<const ConcaveRun> runs,
                           double inwardRad) {
    const std::size_t n = tangents.forwardAngle.size();
    RawChannel channel;
    channel.thetaMax.resize(n);
    channel.thetaMin.resize(n);
    forEachRange(n, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            // E12: forward limit along e+, backward limit along -e-; width pi + tau - 2 inward.
            channel.thetaMax[i] = tangents.forwardAngle[i] - inwardRad;
            channel.thetaMin[i] =
                channel.thetaMax[i] - units::kPi - tangents.turning[i] + 2.0 * inwardRad;
        }
    });
    // The runs at once: each writes only its own samples.
    forEachItem(runs.size(), n, [&channel, runs, n](std::size_t r) {
        const ConcaveRun& run = runs[r];
        // [A] A run without an exit (it reaches the path end) keeps its last sample's limit.
        // Both limits are read before the run is overwritten; an exit is never inside a run
        // (so never inside another run either), and no copy of the convex limits is needed.
        const double exitMax = channel.thetaMax[std::min(run.exit, n - 1)];
        const double entryMin = channel.thetaMin[run.entry];
        double* const thetaMax = channel.thetaMax.data();
        double* const thetaMin = channel.thetaMin.data();
        for (std::size_t j = run.entry; j < std::min(run.exit, n); ++j) {
            thetaMax[j] = exitMax;
            thetaMin[j] = entryMin;
        }
    });
    return channel;
}

void clipGlobalVisibility(RawChannel& channel, std::span<const Vec2> points, std::size_t reach) {
    const std::size_t n = points.size();
    const RawChannel local = channel;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < std::min(n, i + reach + 1); ++j) {
            const Vec2 d = points[j] - points[i];
            const double rel = geometry::wrapAngle(std::atan2(d.y(), d.x()) - local.thetaMax[i]);
            channel.thetaMax[i] = std::min(channel.thetaMax[i], local.thetaMax[i] + rel);
        }
        for (std::size_t j = i > reach ? i - reach : 0; j < i; ++j) {
            const Vec2 d = points[j] - points[i];
            const double rel = geometry::wrapAngle(std::atan2(d.y(), d.x()) - local.thetaMin[i]);
            channel.thetaMin[i] = std::max(channel.thetaMin[i], local.thetaMin[i] + rel);
        }
    }
}

void clipLeadBand(RawChannel& channel, const TangentField& tangents, double minRad, double maxRad) {
    for (std::size_t i = 0; i < channel.thetaMax.size(); ++i) {
        const double normal =
            tangents.forwardAngle[i] - 0.5 * tangents.turning[i] - 0.5 * units::kPi;
        channel.thetaMax[i] = std::min(channel.thetaMax[i], normal + maxRad);
        channel.thetaMin[i] = std::max(channel.thetaMin[i], normal + minRad);
    }
}

namespace {

double median7(std::span<const double> values, std::size_t centre) {
    std::array<double, 7> window{};
    for (std::size_t k = 0; k < 7; ++k) {
        window[k] = values[centre + k - 3];
    }
    std::nth_element(window.begin(), window.begin() + 3, window.end());
    return window[3];
}

std::size_t despikeOne(DefaultInitVector<double>& values, bool downward) {
    const DefaultInitVector<double> original = values;
    std::size_t changed = 0;
    for (std::size_t i = 3; i + 3 < original.size(); ++i) {
        const double median = median7(original, i);
        if (downward ? original[i] < median : original[i] > median) {
            values[i] = median;
            ++changed;
        }
    }
    return changed;
}

} // namespace

std::size_t despikeChannel(RawChannel& channel) {
    return despikeOne(channel.thetaMax, true) + despikeOne(channel.thetaMin, false);
}

MonotoneHull monotoneHull(std::span<const double> thetaMin, std::span<const double> thetaMax,
                          double margin) {
    const std::size_t n = std::min(thetaMin.size(), thetaMax.size());
    MonotoneHull hull;
    if (n == 0) {
        return hull;
    }
    hull.lo0.resize(n);
    hull.hi0.resize(n);
    hull.lo0[0] = thetaMin[0];
    for (std::size_t i = 1; i < n; ++i) {
        hull.lo0[i] = std::max(hull.lo0[i - 1], thetaMin[i]);
    }
    hull.hi0[n - 1] = thetaMax[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) {
        hull.hi0[i] = std::min(hull.hi0[i + 1], thetaMax[i]);
    }
    hull.marginLo.resize(n);
    hull.marginHi.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        hull.infeasible = hull.infeasible || hull.lo0[i] > hull.hi0[i];
        // [A] Local relief (§2.5): a_k = HI0_k - min_k bounds every later thetaMax minus
        // thetaMin_k, b_l = max_l - LO0_l every earlier pair; half of each keeps all pairs
        // k <= l compatible, and equals the full margin wherever no pair is tight.
        hull.marginLo[i] = std::clamp(0.5 * (hull.hi0[i] - thetaMin[i]), 0.0, margin);
        hull.marginHi[i] = std::clamp(0.5 * (thetaMax[i] - hull.lo0[i]), 0.0, margin);
        hull.pinched = hull.pinched || hull.marginLo[i] < margin || hull.marginHi[i] < margin;
    }
    hull.lo.resize(n);
    hull.hi.resize(n);
    hull.lo[0] = thetaMin[0] + hull.marginLo[0];
    for (std::size_t i = 1; i < n; ++i) {
        hull.lo[i] = std::max(hull.lo[i - 1], thetaMin[i] + hull.marginLo[i]);
    }
    hull.hi[n - 1] = thetaMax[n - 1] - hull.marginHi[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) {
        hull.hi[i] = std::min(hull.hi[i + 1], thetaMax[i] - hull.marginHi[i]);
    }
    hull.minWidth = hull.hi[0] - hull.lo[0];
    for (std::size_t i = 0; i < n; ++i) {
        hull.minWidth = std::min(hull.minWidth, hull.hi[i] - hull.lo[i]);
    }
    return hull;
}

namespace {

// HULL0's upper side, HI0_i = min over l >= i of thetaMax_l, written into `hi`.
void upperHull(std::span<const double> thetaMax, std::vector<double>& hi) {
    const std::size_t n = thetaMax.size();
    hi[n - 1] = thetaMax[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) {
        hi[i] = std::min(hi[i + 1], thetaMax[i]);
    }
}

// One forward pass: LO0 as a running value, the margins of §2.5, LO, and HI's per-sample
// candidates thetaMax_i - marginHi_i in place of HI0 (read just before).
void marginsAndLower(std::span<const double> thetaMin, std::span<const double> thetaMax,
                     double margin, MonotoneHull& hull) {
    double lo0 = thetaMin[0];
    for (std::size_t i = 0; i < thetaMin.size(); ++i) {
        lo0 = i == 0 ? lo0 : std::max(lo0, thetaMin[i]);
        const double hi0 = hull.hi[i];
        hull.infeasible = hull.infeasible || lo0 > hi0;
        const double marginLo = std::clamp(0.5 * (hi0 - thetaMin[i]), 0.0, margin);
        const double marginHi = std::clamp(0.5 * (thetaMax[i] - lo0), 0.0, margin);
        hull.pinched = hull.pinched || marginLo < margin || marginHi < margin;
        const double lower = thetaMin[i] + marginLo;
        hull.lo[i] = i == 0 ? lower : std::max(hull.lo[i - 1], lower);
        hull.hi[i] = thetaMax[i] - marginHi;
    }
}

} // namespace

MonotoneHull monotoneBounds(std::span<const double> thetaMin, std::span<const double> thetaMax,
                            double margin) {
    const std::size_t n = std::min(thetaMin.size(), thetaMax.size());
    MonotoneHull hull;
    if (n == 0) {
        return hull;
    }
    thetaMin = thetaMin.first(n);
    thetaMax = thetaMax.first(n);
    hull.lo.resize(n);
    hull.hi.resize(n);
    upperHull(thetaMax, hull.hi);
    marginsAndLower(thetaMin, thetaMax, margin, hull);
    for (std::size_t i = n - 1; i-- > 0;) {
        hull.hi[i] = std::min(hull.hi[i + 1], hull.hi[i]);
    }
    hull.minWidth = hull.hi[0] - hull.lo[0];
    for (std::size_t i = 0; i < n; ++i) {
        hull.minWidth = std::min(hull.minWidth, hull.hi[i] - hull.lo[i]);
    }
    return hull;
}

} // namespace bladeaxis::scheduling

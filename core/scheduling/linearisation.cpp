#include "core/scheduling/linearisation.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

namespace {

// The segment a -> b as theta(S); the slope is divided once, not at every sample.
struct Line {
    double s0, theta0, slope;

    Line(const PolyVertex& a, const PolyVertex& b)
        : s0(a.s), theta0(a.theta), slope((b.theta - a.theta) / (b.s - a.s)) {}
    double at(double s) const { return theta0 + slope * (s - s0); }
};

bool inside(double value, double lo, double hi, double tolerance) {
    return value >= lo - tolerance && value <= hi + tolerance;
}

// Key points of one guidance line (§4.3): the most violating sample under HI (upper key) and
// over LO (lower key), only where they violate ([A] non-violating extremes are not keys).
std::vector<PolyVertex> keysFor(const PolyVertex& a, const PolyVertex& b,
                                const LinearisationInput& in) {
    double worstUpper = -in.toleranceRad;
    double worstLower = in.toleranceRad;
    std::optional<std::size_t> upper;
    std::optional<std::size_t> lower;
    const Line guidance(a, b);
    for (std::size_t j = a.index + 1; j < b.index; ++j) {
        const double g = guidance.at(in.s[j]);
        if (in.hi[j] - g < worstUpper) {
            worstUpper = in.hi[j] - g;
            upper = j;
        }
        if (in.lo[j] - g > worstLower) {
            worstLower = in.lo[j] - g;
            lower = j;
        }
    }
    if (in.keyMode == KeyMode::Worst && upper && lower) {
        (-worstUpper >= worstLower ? lower : upper).reset();
    }
    std::vector<PolyVertex> keys;
    if (upper) {
        keys.push_back({*upper, in.s[*upper], in.hi[*upper], false});
    }
    if (lower) {
        keys.push_back({*lower, in.s[*lower], in.lo[*lower], false});
    }
    std::sort(keys.begin(), keys.end(),
              [](const PolyVertex& x, const PolyVertex& y) { return x.index < y.index; });
    return keys;
}

bool segmentFits(const PolyVertex& a, const PolyVertex& b, const LinearisationInput& in) {
    const Line line(a, b);
    for (std::size_t j = a.index + 1; j < b.index; ++j) {
        if (!inside(line.at(in.s[j]), in.lo[j], in.hi[j], in.toleranceRad)) {
            return false;
        }
    }
    return true;
}

// §4.5 shift: the key moved inward until u -> key -> w is monotone and inside the hull.
std::optional<PolyVertex> shiftedKey(const PolyVertex& u, const PolyVertex& key,
                                     const PolyVertex& w, const LinearisationInput& in) {
    if (!(in.shiftStepRad > 0.0)) {
        return std::nullopt;
    }
    const double direction = key.theta >= in.hi[key.index] ? -1.0 : 1.0; // upper key: down
    const double reach = 0.5 * (in.hi[key.index] - in.lo[key.index]);
    for (double shift = in.shiftStepRad; shift <= reach; shift += in.shiftStepRad) {
        PolyVertex moved = key;
        moved.theta = key.theta + direction * shift;
        if (moved.theta >= u.theta && moved.theta <= w.theta && segmentFits(u, moved, in) &&
            segmentFits(moved, w, in)) {
            return moved;
        }
    }
    return std::nullopt;
}

// refine(A, B) of §4.3 as an explicit depth-first stack (no recursion depth limit): appends
// the vertices after `a` up to and including `b`, left to right.
void refine(const PolyVertex& a, const PolyVertex& b, const LinearisationInput& in,
            Linearisation& out) {
    std::vector<std::pair<PolyVertex, PolyVertex>> stack;
    stack.reserve(8); // one allocation for the usual depth (a few key points per layer)
    stack.emplace_back(a, b);
    while (!stack.empty()) {
        const auto [u, w] = stack.back();
        stack.pop_back();
        const std::vector<PolyVertex> keys = keysFor(u, w, in);
        if (keys.empty()) {
            out.vertices.push_back(w);
            continue;
        }
        if (in.adjust == Adjust::Shift && keys.size() == 1) {
            if (const auto moved = shiftedKey(u, keys.front(), w, in)) {
                out.keyPoints.push_back(*moved);
                out.vertices.push_back(*moved);
                out.vertices.push_back(w);
                continue;
            }
        }
        out.keyPoints.insert(out.keyPoints.end(), keys.begin(), keys.end());
        stack.emplace_back(keys.back(), w);
        for (std::size_t k = keys.size() - 1; k > 0; --k) {
            stack.emplace_back(keys[k - 1], keys[k]);
        }
        stack.emplace_back(u, keys.front());
    }
}

} // namespace

bool segmentInside(const PolyVertex& a, const PolyVertex& b, std::span<const double> s,
                   std::span<const double> lo, std::span<const double> hi, double toleranceRad) {
    const Line line(a, b);
    for (std::size_t j = a.index + 1; j < b.index; ++j) {
        if (!inside(line.at(s[j]), lo[j], hi[j], toleranceRad)) {
            return false;
        }
    }
    return true;
}

LeadLimits leadLimits(std::span<const double> s, std::span<const double> lo,
                      std::span<const double> hi, double startValue, double endValue,
                      double toleranceRad) {
    const std::size_t n = s.size();
    LeadLimits limits;
    while (limits.maxIn + 1 < n &&
           inside(startValue, lo[limits.maxIn + 1], hi[limits.maxIn + 1], toleranceRad)) {
        ++limits.maxIn;
    }
    limits.minOut = n == 0 ? 0 : n - 1;
    while (limits.minOut > 0 &&
           inside(endValue, lo[limits.minOut - 1], hi[limits.minOut - 1], toleranceRad)) {
        --limits.minOut;
    }
    return limits;
}

LeadChoice chooseLeads(std::span<const double> s, const LeadLimits& limits, double rho,
                       bool freeStart, bool freeEnd) {
    const std::size_t n = s.size();
    LeadChoice leads;
    if (n < 4) {
        return leads;
    }
    const double length = s.back() - s.front();
    if (!freeStart) {
        // The last sample with S - S_0 <= rho S_e (S increasing: a partition point).
        const auto after = std::partition_point(
            s.begin() + 1, s.end(), [&](double x) { return x - s.front() <= rho * length; });
        const auto index = static_cast<std::size_t>(after - s.begin()) - 1;
        leads.zeroLengthLead = limits.maxIn == 0 || index == 0;
        leads.leadIn = std::clamp<std::size_t>(std::min(index, limits.maxIn), 1, n - 2);
    }
    if (!freeEnd) {
        // The first sample from which every S_e - S <= rho S_e (up to the last but one).
        const auto index = static_cast<std::size_t>(
            std::partition_point(s.begin(), s.end() - 1,
                                 [&](double x) { return s.back() - x > rho * length; }) -
            s.begin());
        leads.zeroLengthLead = leads.zeroLengthLead || limits.minOut == n - 1 || index == n - 1;
        leads.leadOut = std::clamp<std::size_t>(std::max(index, limits.minOut), 1, n - 2);
    }
    if (leads.leadIn && leads.leadOut && *leads.leadIn >= *leads.leadOut) {
        // [A] Leads longer than the layer allows: split the overlap, keep one sample between.
        const std::size_t middle = (*leads.leadIn + *leads.leadOut) / 2;
        leads.leadIn = std::clamp<std::size_t>(middle, 1, n - 3);
        leads.leadOut = *leads.leadIn + 1;
    }
    return leads;
}

LeadChoice chooseLeads(std::span<const double> s, std::span<const double> lo,
                       std::span<const double> hi, double startValue, double endValue, double rho,
                       bool freeStart, bool freeEnd, double toleranceRad) {
    return chooseLeads(s, leadLimits(s, lo, hi, startValue, endValue, toleranceRad), rho, freeStart,
                       freeEnd);
}

Linearisation linearise(const LinearisationInput& in) {
    Linearisation out;
    const std::size_t n = in.s.size();
    if (n == 0) {
        return out;
    }
    const PolyVertex start{0, in.s[0], in.startValue, true};
    const PolyVertex end{n - 1, in.s[n - 1], in.endValue, true};
    if (n == 1) {
        out.vertices = {start};
        return out;
    }
    out.vertices.reserve(16); // one allocation for the usual polyline (4 fixed vertices + keys)
    out.vertices.push_back(start);
    PolyVertex rampStart = start;
    PolyVertex rampEnd = end;
    if (in.leads.leadIn) {
        rampStart = {*in.leads.leadIn, in.s[*in.leads.leadIn], in.startValue, true};
        out.vertices.push_back(rampStart);
    }
    if (in.leads.leadOut) {
        rampEnd = {*in.leads.leadOut, in.s[*in.leads.leadOut], in.endValue, true};
    }
    refine(rampStart, rampEnd, in, out);
    if (in.leads.leadOut) {
        out.vertices.push_back(end);
    }
    out.vertices = removeRedundant(std::move(out.vertices), in.s, in.lo, in.hi, in.toleranceRad);
    return out;
}

std::vector<PolyVertex> removeRedundant(std::vector<PolyVertex> vertices, std::span<const double> s,
                                        std::span<const double> lo, std::span<const double> hi,
                                        double toleranceRad) {
    bool changed = true;
    while (changed) {
        changed = false;
        for (std::size_t k = 1; k + 1 < vertices.size();) {
            if (!vertices[k].fixed &&
                segmentInside(vertices[k - 1], vertices[k + 1], s, lo, hi, toleranceRad)) {
                vertices.erase(vertices.begin() + static_cast<long>(k));
                changed = true;
            } else {
                ++k;
            }
        }
    }
    return vertices;
}

} // namespace bladeaxis::scheduling

#include "core/scheduling/linearisation.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

namespace {

double lineAt(const PolyVertex& a, const PolyVertex& b, double s) {
    return a.theta + (b.theta - a.theta) * (s - a.s) / (b.s - a.s);
}

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
    for (std::size_t j = a.index + 1; j < b.index; ++j) {
        const double g = lineAt(a, b, in.s[j]);
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

// refine(A, B) of §4.3 as an explicit depth-first stack (no recursion depth limit): appends
// the vertices after `a` up to and including `b`, left to right.
void refine(const PolyVertex& a, const PolyVertex& b, const LinearisationInput& in,
            Linearisation& out) {
    std::vector<std::pair<PolyVertex, PolyVertex>> stack{{a, b}};
    while (!stack.empty()) {
        const auto [u, w] = stack.back();
        stack.pop_back();
        const std::vector<PolyVertex> keys = keysFor(u, w, in);
        if (keys.empty()) {
            out.vertices.push_back(w);
            continue;
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
    for (std::size_t j = a.index + 1; j < b.index; ++j) {
        if (!inside(lineAt(a, b, s[j]), lo[j], hi[j], toleranceRad)) {
            return false;
        }
    }
    return true;
}

LeadChoice chooseLeads(std::span<const double> s, std::span<const double> lo,
                       std::span<const double> hi, double startValue, double endValue, double rho,
                       bool freeStart, bool freeEnd, double toleranceRad) {
    const std::size_t n = s.size();
    LeadChoice leads;
    if (n < 4) {
        return leads;
    }
    const double length = s.back() - s.front();
    if (!freeStart) {
        std::size_t maxIn = 0; // S_a,max: last sample of the run from 0 where start is inside
        while (maxIn + 1 < n && inside(startValue, lo[maxIn + 1], hi[maxIn + 1], toleranceRad)) {
            ++maxIn;
        }
        std::size_t index = 0;
        while (index + 1 < n && s[index + 1] - s.front() <= rho * length) {
            ++index;
        }
        leads.zeroLengthLead = maxIn == 0 || index == 0;
        leads.leadIn = std::clamp<std::size_t>(std::min(index, maxIn), 1, n - 2);
    }
    if (!freeEnd) {
        std::size_t minOut = n - 1; // S_b,min
        while (minOut > 0 && inside(endValue, lo[minOut - 1], hi[minOut - 1], toleranceRad)) {
            --minOut;
        }
        std::size_t index = n - 1;
        while (index > 0 && s.back() - s[index - 1] <= rho * length) {
            --index;
        }
        leads.zeroLengthLead = leads.zeroLengthLead || minOut == n - 1 || index == n - 1;
        leads.leadOut = std::clamp<std::size_t>(std::max(index, minOut), 1, n - 2);
    }
    if (leads.leadIn && leads.leadOut && *leads.leadIn >= *leads.leadOut) {
        // [A] Leads longer than the layer allows: split the overlap, keep one sample between.
        const std::size_t middle = (*leads.leadIn + *leads.leadOut) / 2;
        leads.leadIn = std::clamp<std::size_t>(middle, 1, n - 3);
        leads.leadOut = *leads.leadIn + 1;
    }
    return leads;
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

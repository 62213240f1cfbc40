#pragma once
// Spec §3.4 and §4: lead-in/lead-out choice, recursive key points on the monotone hull, and
// redundant key point removal. Vertices sit at sample indices of one layer.

#include "core/scheduling/schedule_parameters.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace bladeaxis::scheduling {

struct PolyVertex {
    std::size_t index = 0; // sample index within the layer
    double s = 0.0;        // S, mm
    double theta = 0.0;    // rad, relative to the layer reference
    bool fixed = false;    // end or lead vertex: never removed (§4.4)
};

struct LeadChoice {
    std::optional<std::size_t> leadIn;  // sample index of (S_a, start); none for a free start
    std::optional<std::size_t> leadOut; // sample index of (S_b, end); none for a free end
    bool zeroLengthLead = false;        // S_a,max or S_b,min forced a one-sample lead (§4.6)
};

struct LinearisationInput {
    std::span<const double> s, lo, hi; // layer samples and monotone hull (relative), mm / rad
    double startValue = 0.0;
    double endValue = 0.0;
    LeadChoice leads;
    KeyMode keyMode = KeyMode::Both;
    double toleranceRad = 1e-9;
    // §4.5 adjust = shift: a single key is first moved inward (upper keys down, lower keys up)
    // in steps of shiftStepRad (m / 10) up to half the local hull width, until both new
    // segments are inside; otherwise the recursion runs as usual.
    Adjust adjust = Adjust::Recursive;
    double shiftStepRad = 0.0;
};

struct Linearisation {
    std::vector<PolyVertex> keyPoints; // every key point the recursion inserted (§4.3)
    std::vector<PolyVertex> vertices;  // final polyline after redundancy removal (§4.4)
};

// §3.4: S_a = min(rho S_e, S_a,max), S_b = max((1 - rho) S_e, S_b,min), snapped to samples.
// `freeStart` / `freeEnd` drop the lead on that side (§3.3).
LeadChoice chooseLeads(std::span<const double> s, std::span<const double> lo,
                       std::span<const double> hi, double startValue, double endValue, double rho,
                       bool freeStart, bool freeEnd, double toleranceRad);

// The rho-independent part of chooseLeads, computed once per layer for the lead search:
// S_a,max and S_b,min as sample indices.
struct LeadLimits {
    std::size_t maxIn = 0;  // last sample of the run from 0 where the start value is inside
    std::size_t minOut = 0; // first sample of the run to the end where the end value is inside
};
LeadLimits leadLimits(std::span<const double> s, std::span<const double> lo,
                      std::span<const double> hi, double startValue, double endValue,
                      double toleranceRad);
LeadChoice chooseLeads(std::span<const double> s, const LeadLimits& limits, double rho,
                       bool freeStart, bool freeEnd);

Linearisation linearise(const LinearisationInput& input);

// §4.4: repeatedly delete interior non-fixed vertices whose neighbours can be joined inside
// [lo, hi] at every sample between them. Idempotent.
std::vector<PolyVertex> removeRedundant(std::vector<PolyVertex> vertices, std::span<const double> s,
                                        std::span<const double> lo, std::span<const double> hi,
                                        double toleranceRad);

// True when the segment a -> b lies within [lo - tol, hi + tol] at every sample strictly
// between their indices.
bool segmentInside(const PolyVertex& a, const PolyVertex& b, std::span<const double> s,
                   std::span<const double> lo, std::span<const double> hi, double toleranceRad);

} // namespace bladeaxis::scheduling

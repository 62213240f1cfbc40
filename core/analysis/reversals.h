#pragma once
// Rotary-axis direction audit (spec §6.4): reversals, travel and backward travel of A.
// Angles in rad.

#include "core/base/tolerances.h"

#include <cstddef>
#include <span>
#include <vector>

namespace bladeaxis::analysis {

struct ReversalAudit {
    int count = 0;                    // sign changes of dA over steps with |dA| > minStep
    std::vector<std::size_t> indices; // index of the sample where each new direction starts
    double travel = 0.0;              // total |dA|, rad (every finite step, tiny ones included)
    double backwardTravel = 0.0;      // rad travelled against the dominant direction
};

// Counts direction reversals of a rotary axis. Steps with |dA| <= minStep are treated as
// standstill: they neither count nor reset the direction, so positioning noise below the
// threshold cannot create reversals. Non-finite steps are skipped. The dominant direction is
// the one with the larger total travel, so backwardTravel = min(forward, backward) travel.
ReversalAudit auditReversals(std::span<const double> a, double minStep = tol::kReversalStepRad);

// Unwraps a modulo-programmed rotary axis (e.g. A in [0, 2pi)) so that consecutive steps lie in
// (-pi, pi], the shortest way a modulo controller moves. Non-finite entries stay non-finite and
// the following finite values continue from the last finite one (one bad value does not poison
// the rest of the program).
std::vector<double> unwrapRotary(std::span<const double> a);

} // namespace bladeaxis::analysis

#pragma once
// Machine-limit sweep of spec §8.3: how T2 reacts when the rotary axes (A, B) are made slower or
// faster, velocity and acceleration (and jerk) scaled together by one factor.

#include "core/analysis/time_optimal.h"

#include <vector>

namespace bladeaxis::analysis {

struct LimitSweepPoint {
    double factor = 1.0; // rotary limits x factor
    double time = 0.0;   // s, T2 at those limits; NaN when T2 failed for this factor
};

// The factors 0.5, 0.75, 1, 1.5, 2 of the spec's sweep.
std::vector<double> defaultRotarySweepFactors();

// The machine with the rotary (A, B) velocity, acceleration and jerk limits x factor; an
// unlimited (<= 0) limit stays unlimited.
kinematics::MachineModel scaledRotaryLimits(const kinematics::MachineModel& machine, double factor);

// T2 for each factor (in the given order). A factor <= 0 or non-finite is an InvalidArgument
// error; a T2 failure at one factor is reported as a NaN time so the other points survive.
Result<std::vector<LimitSweepPoint>> sweepRotaryLimits(const AxisProfile& profile,
                                                       const kinematics::MachineModel& machine,
                                                       const std::vector<double>& factors,
                                                       const TimeOptimalOptions& options = {});

} // namespace bladeaxis::analysis

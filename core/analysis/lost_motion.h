#pragma once
// Backlash against the motion: at each direction change of an axis with play, the drive turns
// through the play before the slide or table follows (or, compensated, jumps by it), which marks
// the surface. A monotone A removes that for the rotary axis; the report shows before and after.

#include "core/analysis/axis_profile.h"
#include "core/kinematics/machine_model.h"

#include <vector>

namespace bladeaxis::analysis {

struct LostMotion {
    kinematics::AxisId axis = kinematics::AxisId::A;
    double backlash = 0.0;   // mm or rad, from the machine file
    int reversals = 0;       // direction changes of the axis over the pass
    double lostMotion = 0.0; // reversals x backlash, mm or rad
};

// Linear steps below this are standstill (a post's 1 um rounding never makes a reversal).
inline constexpr double kLinearReversalStepMm = 1e-6;

// One entry per axis whose backlash is positive, in X Y Z A B order. A's reversals are the
// profile's audit over every record; the others count sign changes of the sampled positions.
std::vector<LostMotion> lostMotion(const AxisProfile& profile,
                                   const kinematics::MachineModel& machine);

} // namespace bladeaxis::analysis

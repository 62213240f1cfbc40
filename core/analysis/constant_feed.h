#pragma once
// T1 of spec §8.3: the highest constant feed the axis limits allow along the analysed path,
// and the machining time at that feed.

#include "core/analysis/axis_profile.h"
#include "core/kinematics/machine_model.h"

namespace bladeaxis::analysis {

struct ConstantFeedTime {
    enum class Binding { Programmed, Velocity, Acceleration, Jerk };

    double feed = 0.0;           // mm/s, the profile's (programmed) feed F
    double achievableFeed = 0.0; // mm/s, F* <= F
    double time = 0.0;           // s, T1 = s_total / F*
    // The axis whose limit allows the lowest feed, even when F itself binds (then it is the axis
    // closest to its limit); X when no axis moves.
    kinematics::AxisId bindingAxis = kinematics::AxisId::X;
    Binding binding = Binding::Programmed;
};

// F* = min(F, min_j v_j / max|q_j'|, min_j sqrt(a_j / max|q_j''|), [min_j cbrt(J_j /
// max|q_j'''|)]). max|q_j^(k)| comes from the profile's peaks (peak / F^k). Limits are in the
// machine model's internal units (mm, rad, s: a limit written in deg/s in the machine file is
// already rad/s). A limit <= 0 or non-finite means "unlimited" for that quantity; an axis whose
// derivative is zero never binds. A profile without a positive feed gives feed 0 and time 0.
ConstantFeedTime constantFeedTime(const AxisProfile& profile,
                                  const kinematics::MachineModel& machine, bool includeJerk);

} // namespace bladeaxis::analysis

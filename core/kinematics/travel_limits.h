#pragma once
// The machine's travel limits against a motion: a program that drives an axis beyond its
// travel stops the machine with an overtravel alarm mid-cut (or worse, where soft limits are
// off), so the written program is checked before it is written and the input is reported.

#include "core/kinematics/machine_model.h"

#include <optional>
#include <span>
#include <string>

namespace bladeaxis::kinematics {

struct TravelExcess {
    AxisId axis = AxisId::X;
    std::size_t index = 0; // into the axes checked
    double value = 0.0;    // mm or rad
    double min = 0.0, max = 0.0;
    double amount = 0.0; // how far beyond the nearer limit, mm or rad (> 0)
};

// The first sample (in order) where an axis with a travel range leaves it by more than
// `tolerance` (mm for linear axes, rad for rotary ones: the control's resolution). Axes
// without a travel range (a continuous rotary axis) are not checked.
std::optional<TravelExcess> firstTravelExcess(std::span<const MachineAxes> axes,
                                              const MachineModel& machine, double tolerance = 1e-6);

// "X = 1450.000 mm, 50.000 mm beyond the travel [-1400.000, 1400.000] mm": display units
// (mm, deg), in the program's terms (its letter, its sign).
std::string describe(const TravelExcess& excess, const MachineModel& machine);

} // namespace bladeaxis::kinematics

#include "core/kinematics/travel_limits.h"

#include "core/base/units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace bladeaxis::kinematics {

std::optional<TravelExcess> firstTravelExcess(std::span<const MachineAxes> axes,
                                              const MachineModel& machine, double tolerance) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
        for (const AxisId axis : kAllAxes) {
            const AxisLimits& limit = machine.limit(axis);
            if (!limit.hasTravel) {
                continue;
            }
            const double value = axes[i][axis];
            const double below = limit.min - value, above = value - limit.max;
            if (below > tolerance || above > tolerance || std::isnan(value)) {
                return TravelExcess{axis,      i,
                                    value,     limit.min,
                                    limit.max, std::isnan(value) ? 0.0 : std::max(below, above)};
            }
        }
    }
    return std::nullopt;
}

std::string describe(const TravelExcess& excess, const MachineModel& machine) {
    const bool rotary = isRotary(excess.axis);
    const double sign = machine.programWord(excess.axis).sign;
    const double scale = (rotary ? units::radToDeg(1.0) : 1.0) * sign;
    // A mirrored word's travel [min, max] is the engine's [-max, -min].
    const double low = sign > 0.0 ? excess.min : excess.max;
    const double high = sign > 0.0 ? excess.max : excess.min;
    const char* unit = rotary ? "deg" : "mm";
    char text[200];
    std::snprintf(text, sizeof text, "%s = %.3f %s, %.3f %s beyond the travel [%.3f, %.3f] %s",
                  std::string(1, machine.letter(excess.axis)).c_str(), excess.value * scale, unit,
                  excess.amount * std::abs(scale), unit, low * scale, high * scale, unit);
    return text;
}

} // namespace bladeaxis::kinematics

#pragma once
// How the control moves an axis for a word, shared by the reader (where a word takes the axis)
// and the writer (which word takes it where the schedule wants it).

#include "core/base/units.h"
#include "core/io/nc/gcode_program.h"

#include <array>
#include <cmath>

namespace bladeaxis::io::nc::detail {

// `delta` (rad) brought into [0, 2 pi): the turn in the positive direction.
inline double turnsUp(double delta) {
    const double r = std::fmod(delta, units::kTwoPi);
    return r < 0.0 ? r + units::kTwoPi : r;
}

// The position a modulo-form word (DC or M126: the shorter way, ACP: up, ACN: down) for
// `target` reaches from `from`; all in rad.
inline double reachedByModulo(RotaryForm form, double from, double target) {
    switch (form) {
    case RotaryForm::Positive:
        return from + turnsUp(target - from);
    case RotaryForm::Negative:
        return from - turnsUp(from - target);
    default:
        return from + std::remainder(target - from, units::kTwoPi);
    }
}

// The length of a move as a combined-axes control measures it for F: linear axes (mm) in the
// program's unit (inch with G20), rotary axes (rad) in degrees, all in one vector.
inline double combinedAxisMove(const std::array<double, 5>& from, const std::array<double, 5>& to,
                               bool inch) {
    double sum = 0.0;
    for (std::size_t axis = 0; axis < from.size(); ++axis) {
        const double step = to[axis] - from[axis];
        const double file =
            axis >= 3 ? units::radToDeg(step) : (inch ? units::mmToInch(step) : step);
        sum += file * file;
    }
    return std::sqrt(sum);
}

} // namespace bladeaxis::io::nc::detail

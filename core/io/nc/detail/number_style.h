#pragma once
// How a file writes its numbers, so that rewritten and inserted words look like their
// neighbours: decimals, a leading zero or not (".5"), an explicit '+', trailing-zero trimming.

#include "core/io/nc/gcode_program.h"

#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis::io::nc::detail {

// The style of one written number.
struct WordTextStyle {
    int decimals = 0;
    bool hasPoint = false;
    std::optional<bool> leadingZero; // known only when the integer part is zero ("0.5" / ".5")
    bool explicitPlus = false;
};

WordTextStyle styleOfWord(std::string_view text);

// Adds one word of an axis to what is known about that axis' style.
void noteAxisWord(AxisNumberStyle& axis, std::string_view text);

// `value` (file units) written the way the word `old` was written, within the axis' style.
std::string formatLikeWord(double value, std::string_view old, const AxisNumberStyle& axis);

// `value` (file units) written as a new word of that axis.
std::string formatForInsertion(double value, const AxisNumberStyle& axis);

} // namespace bladeaxis::io::nc::detail

#pragma once
// How a file writes its numbers, so that rewritten and inserted words look like their
// neighbours: decimals, a leading zero or not (".5"), an explicit '+', trailing-zero trimming.

#include "core/base/number_io.h"
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

// styleOfWord for a number the scanner read as a plain decimal (`text` starts with it), from
// what it learnt on the way: no second pass over the text. Set in place, field by field, in the
// word the scanner fills (block_scanner.cpp says why); inline, as it runs for every word.
inline void setPlainDecimalStyle(WordTextStyle& style, std::string_view text,
                                 const PlainDecimal& number) {
    style.explicitPlus = text.front() == '+';
    style.hasPoint = number.hasPoint;
    style.decimals = static_cast<int>(number.fractionDigits);
    if (!number.hasPoint) {
        style.leadingZero.reset();
    } else if (number.integerDigits == 0) {
        style.leadingZero = false;
    } else if (number.integerPartZero) {
        style.leadingZero = true;
    } else {
        style.leadingZero.reset();
    }
}

// Adds one word of an axis, written in `word` style, to what is known about that axis' style.
void noteAxisWord(AxisNumberStyle& axis, const WordTextStyle& word);

// A word's number and what parseNumber reads it back as, when that is known without parsing it.
struct WordNumber {
    std::string text;
    std::optional<double> value;
};

// `value` (file units) written the way the word `old` was written, within the axis' style.
WordNumber numberLikeWord(double value, std::string_view old, const AxisNumberStyle& axis);
// The same for an old word whose style is known already (styleOfWord or setPlainDecimalStyle).
WordNumber numberInWordStyle(double value, const WordTextStyle& word, const AxisNumberStyle& axis);

// `value` (file units) written as a new word of that axis.
std::string formatForInsertion(double value, const AxisNumberStyle& axis);

} // namespace bladeaxis::io::nc::detail

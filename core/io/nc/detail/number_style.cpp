#include "core/io/nc/detail/number_style.h"

#include "core/base/number_io.h"

#include <algorithm>

namespace bladeaxis::io::nc::detail {

namespace {

// Decimals written when an axis never appears, or trims zeros with fewer decimals seen: enough
// for 0.1 um and 0.0001 deg, more than the control resolves, so nothing is lost.
constexpr int kDefaultDecimals = 4;

// A formatted number (fixedText / trimmedText) in a word's style: a point added when `wantPoint`
// and it has none, "0." shortened to "." without `leadingZero`, a '+' before a positive number
// with `explicitPlus`. Built in one pass: it runs for every changed word.
WordNumber decorated(const NumberText& number, bool wantPoint, bool leadingZero,
                     bool explicitPlus) {
    const std::string_view digits = number.view();
    const bool negative = digits.starts_with('-');
    const std::string_view body = negative ? digits.substr(1) : digits;
    // A loop over a dozen characters, cheaper than the memchr call find() makes.
    const bool addPoint =
        wantPoint && std::ranges::none_of(body, [](char ch) { return ch == '.'; });
    const bool pointAfterFirst = body.size() > 1 ? body[1] == '.' : addPoint;
    const bool dropZero = !leadingZero && body.starts_with('0') && pointAfterFirst;
    WordNumber word;
    if (negative || explicitPlus) {
        word.text += negative ? '-' : '+';
    }
    word.text.append(dropZero ? body.substr(1) : body);
    if (addPoint) {
        word.text += '.';
    }
    // Neither the point nor a sign changes the value the digits read as; "." alone has no digit
    // and parseNumber refuses it.
    const bool lostTheOnlyDigit = dropZero && body.size() == 1;
    word.value = lostTheOnlyDigit ? std::nullopt : number.value;
    return word;
}

int trimmedDecimals(const AxisNumberStyle& axis) {
    return std::max(axis.maxDecimals, kDefaultDecimals);
}

} // namespace

WordTextStyle styleOfWord(std::string_view text) {
    WordTextStyle style;
    std::size_t i = 0;
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        style.explicitPlus = text[0] == '+';
        ++i;
    }
    const std::size_t point = text.find('.', i);
    if (point == std::string_view::npos) {
        return style;
    }
    style.hasPoint = true;
    const std::string_view integerPart = text.substr(i, point - i);
    if (integerPart.empty()) {
        style.leadingZero = false;
    } else if (integerPart.find_first_not_of('0') == std::string_view::npos) {
        style.leadingZero = true;
    }
    std::size_t end = point + 1;
    while (end < text.size() && text[end] >= '0' && text[end] <= '9') {
        ++end;
    }
    style.decimals = static_cast<int>(end - point - 1);
    return style;
}

void noteAxisWord(AxisNumberStyle& axis, const WordTextStyle& word) {
    if (!axis.seen) {
        axis.seen = true;
        axis.minDecimals = word.decimals;
        axis.maxDecimals = word.decimals;
    }
    axis.minDecimals = std::min(axis.minDecimals, word.decimals);
    axis.maxDecimals = std::max(axis.maxDecimals, word.decimals);
    axis.trailingPoint = axis.trailingPoint || (word.hasPoint && word.decimals == 0);
    axis.explicitPlus = axis.explicitPlus || word.explicitPlus;
    if (word.leadingZero) {
        axis.leadingZero = *word.leadingZero;
    }
}

WordNumber numberLikeWord(double value, std::string_view old, const AxisNumberStyle& axis) {
    return numberInWordStyle(value, styleOfWord(old), axis);
}

WordNumber numberInWordStyle(double value, const WordTextStyle& word, const AxisNumberStyle& axis) {
    const NumberText number = axis.trimsZeros() ? trimmedText(value, trimmedDecimals(axis))
                                                : fixedText(value, word.decimals);
    return decorated(number, word.hasPoint, word.leadingZero.value_or(axis.leadingZero),
                     word.explicitPlus);
}

std::string formatForInsertion(double value, const AxisNumberStyle& axis) {
    const bool trims = axis.trimsZeros();
    const NumberText number = !axis.seen ? fixedText(value, kDefaultDecimals)
                              : trims    ? trimmedText(value, trimmedDecimals(axis))
                                         : fixedText(value, axis.maxDecimals);
    const bool wantPoint = axis.seen && (trims ? axis.trailingPoint : axis.maxDecimals == 0);
    return decorated(number, wantPoint, axis.leadingZero, axis.explicitPlus).text;
}

} // namespace bladeaxis::io::nc::detail

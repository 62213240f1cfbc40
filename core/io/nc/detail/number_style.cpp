#include "core/io/nc/detail/number_style.h"

#include "core/base/number_io.h"

#include <algorithm>

namespace bladeaxis::io::nc::detail {

namespace {

// Decimals written when an axis never appears, or trims zeros with fewer decimals seen: enough
// for 0.1 um and 0.0001 deg, more than the control resolves, so nothing is lost.
constexpr int kDefaultDecimals = 4;

// Applies leading-zero and sign conventions to a formatFixed/formatTrimmed result.
std::string decorate(std::string text, bool leadingZero, bool explicitPlus) {
    const bool negative = !text.empty() && text.front() == '-';
    const std::size_t digits = negative ? 1 : 0;
    if (!leadingZero && text.size() > digits + 1 && text[digits] == '0' &&
        text[digits + 1] == '.') {
        text.erase(digits, 1);
    }
    if (explicitPlus && !negative) {
        text.insert(text.begin(), '+');
    }
    return text;
}

std::string withTrailingPoint(std::string text, bool wantPoint) {
    if (wantPoint && text.find('.') == std::string::npos) {
        text += '.';
    }
    return text;
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

std::string formatLikeWord(double value, std::string_view old, const AxisNumberStyle& axis) {
    const WordTextStyle word = styleOfWord(old);
    std::string text;
    if (axis.trimsZeros()) {
        text = withTrailingPoint(formatTrimmed(value, trimmedDecimals(axis)), word.hasPoint);
    } else {
        text = withTrailingPoint(formatFixed(value, word.decimals), word.hasPoint);
    }
    return decorate(std::move(text), word.leadingZero.value_or(axis.leadingZero),
                    word.explicitPlus);
}

std::string formatForInsertion(double value, const AxisNumberStyle& axis) {
    std::string text;
    if (!axis.seen) {
        text = formatFixed(value, kDefaultDecimals);
    } else if (axis.trimsZeros()) {
        text = withTrailingPoint(formatTrimmed(value, trimmedDecimals(axis)), axis.trailingPoint);
    } else {
        text = withTrailingPoint(formatFixed(value, axis.maxDecimals), axis.maxDecimals == 0);
    }
    return decorate(std::move(text), axis.leadingZero, axis.explicitPlus);
}

} // namespace bladeaxis::io::nc::detail

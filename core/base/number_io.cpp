#include "core/base/number_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace bladeaxis {

namespace {

// Any decimal, through from_chars: exponents, long digit strings, range errors.
std::optional<double> parseAnyDecimal(std::string_view token) {
    // from_chars accepts neither a leading '+' nor a bare leading '.', which NC files use.
    std::string_view body = token;
    bool negative = false;
    if (body.front() == '+' || body.front() == '-') {
        negative = body.front() == '-';
        body.remove_prefix(1);
    }
    if (body.empty() ||
        !(std::isdigit(static_cast<unsigned char>(body.front())) || body.front() == '.')) {
        return std::nullopt;
    }
    if (body.front() == '.' &&
        (body.size() < 2 || !std::isdigit(static_cast<unsigned char>(body[1])))) {
        return std::nullopt; // "." alone or ".e5" carries no digits
    }
    std::array<char, 64> buffer{};
    std::string_view digits = body;
    if (body.front() == '.') {
        if (body.size() + 1 >= buffer.size()) {
            return std::nullopt;
        }
        buffer[0] = '0';
        body.copy(buffer.data() + 1, body.size());
        digits = std::string_view(buffer.data(), body.size() + 1);
    }
    double value = 0.0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value,
                                     std::chars_format::general);
    if (ec != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value)) {
        // "5." is accepted by from_chars (it consumes the point); anything left over is garbage.
        return std::nullopt;
    }
    return negative ? -value : value;
}

} // namespace

std::optional<double> parseNumber(std::string_view token) {
    if (token.empty()) {
        return std::nullopt;
    }
    // Nearly every number in a program is a short plain decimal, several times faster to read
    // directly than through from_chars.
    if (const PlainDecimal plain = readPlainDecimal(token); plain.length == token.size()) {
        return plain.value;
    }
    return parseAnyDecimal(token);
}

namespace {

constexpr int kMaxExactDecimals = static_cast<int>(kMaxPlainDigits);
// Below 2^50 the fraction of a scaled value is resolved to at least 1/8.
constexpr double kMaxExactScaled = 0x1p50;

// |value| rounded to `decimals` places, as the integer of its digits, when the double product
// alone settles it; nullopt leaves the case to to_chars. 10^decimals is exact, so the product is
// rounded once and lies within half an ulp of the true one. Rounding to the nearest integer
// changes only at a half, so unless the product's fraction is within that error of one half
// (a near tie, or a true one such as 0.125 to 2 places, which to_chars breaks its own way),
// the true product rounds to the same integer as the computed one.
std::optional<std::uint64_t> exactlyRoundedDigits(double magnitude, int decimals) {
    if (decimals < 0 || decimals > kMaxExactDecimals) {
        return std::nullopt;
    }
    const double scaled = magnitude * kExactPowersOfTen[static_cast<std::size_t>(decimals)];
    if (!(scaled < kMaxExactScaled)) { // also NaN and infinity
        return std::nullopt;
    }
    const auto whole = static_cast<std::uint64_t>(scaled);
    const double fraction = scaled - static_cast<double>(whole); // exact: both are doubles
    const double twoUlps = scaled * 0x1p-51;                     // ulp(scaled) <= scaled * 2^-52
    if (std::abs(fraction - 0.5) <= twoUlps) {
        return std::nullopt;
    }
    return fraction > 0.5 ? whole + 1 : whole;
}

constexpr std::array<std::uint64_t, kMaxExactDecimals + 1> kIntegerPowersOfTen = [] {
    std::array<std::uint64_t, kMaxExactDecimals + 1> powers{};
    std::uint64_t power = 1;
    for (std::uint64_t& entry : powers) {
        entry = power;
        power *= 10;
    }
    return powers;
}();

// "00" to "99": two digits per division, half the dependent steps of one at a time.
constexpr std::array<char, 200> kDigitPairs = [] {
    std::array<char, 200> pairs{};
    for (std::size_t i = 0; i < 100; ++i) {
        pairs[2 * i] = static_cast<char>('0' + i / 10);
        pairs[2 * i + 1] = static_cast<char>('0' + i % 10);
    }
    return pairs;
}();

// Decimal digits of a value below 10^16 (none for 0), from its bit width: log10(2) ~ 1233/4096.
std::size_t decimalDigitCount(std::uint64_t value) {
    const auto estimate = static_cast<std::size_t>((std::bit_width(value) * 1233) >> 12);
    return estimate + (value >= kIntegerPowersOfTen[estimate] ? 1 : 0);
}

// Writes the last `count` decimal digits of `value`, zero-padded, ending at `end`; returns the
// digits ahead of them.
std::uint64_t writeDigitsBackwards(char* end, std::uint64_t value, std::size_t count) {
    for (; count >= 2; count -= 2) {
        end -= 2;
        std::copy_n(&kDigitPairs[2 * (value % 100)], 2, end);
        value /= 100;
    }
    if (count == 1) {
        *--end = static_cast<char>('0' + value % 10);
        value /= 10;
    }
    return value;
}

// `digits` with a point before the last `decimals` of them, as to_chars writes a fixed value:
// at least one digit before the point, none without decimals.
NumberText fixedFromDigits(bool negative, std::uint64_t digits, int decimals) {
    const auto fractionDigits = static_cast<std::size_t>(decimals);
    // A value that rounds to zero is written without a sign: controllers and diffs prefer "0.000".
    const bool sign = negative && digits != 0;
    NumberText text;
    // parseNumber reads these digits as one integer over a power of ten, correctly rounded like
    // this quotient of two exact doubles (or through from_chars past 15 digits, equally so).
    const double magnitude = static_cast<double>(digits) / kExactPowersOfTen[fractionDigits];
    text.value = sign ? -magnitude : magnitude;
    // Written in place, back to front, once the length is known: no copy of a scratch buffer.
    const std::size_t integerDigits =
        std::max(decimalDigitCount(digits), fractionDigits + 1) - fractionDigits;
    text.size = (sign ? 1 : 0) + integerDigits + (fractionDigits != 0 ? 1 + fractionDigits : 0);
    char* const end = text.chars.data() + text.size;
    const std::uint64_t integerPart = writeDigitsBackwards(end, digits, fractionDigits);
    char* const integerEnd = fractionDigits != 0 ? end - fractionDigits - 1 : end;
    if (fractionDigits != 0) {
        *integerEnd = '.';
    }
    writeDigitsBackwards(integerEnd, integerPart, integerDigits);
    if (sign) {
        text.chars[0] = '-';
    }
    return text;
}

NumberText shortestText(double value) {
    NumberText text;
    auto [end, ec] = std::to_chars(text.chars.data(), text.chars.data() + text.chars.size(), value);
    (void)ec; // 64 characters always suffice for the shortest form of a double
    text.size = static_cast<std::size_t>(end - text.chars.data());
    return text;
}

NumberText fixedThroughToChars(double value, int decimals) {
    NumberText text;
    auto [end, ec] = std::to_chars(text.chars.data(), text.chars.data() + text.chars.size(), value,
                                   std::chars_format::fixed, decimals);
    if (ec != std::errc{}) {
        return shortestText(value);
    }
    text.size = static_cast<std::size_t>(end - text.chars.data());
    // A value that rounds to zero is written without a sign: controllers and diffs prefer "0.000".
    if (text.chars[0] == '-' && text.view().find_first_not_of("-0.") == std::string_view::npos) {
        std::copy(text.chars.begin() + 1,
                  text.chars.begin() + static_cast<std::ptrdiff_t>(text.size), text.chars.begin());
        --text.size;
    }
    return text;
}

} // namespace

NumberText fixedText(double value, int decimals) {
    // to_chars with a precision is exact for every double but slow; the digits of nearly every
    // coordinate are settled by one multiplication.
    if (const auto digits = exactlyRoundedDigits(std::abs(value), decimals)) {
        return fixedFromDigits(std::signbit(value), *digits, decimals);
    }
    return fixedThroughToChars(value, decimals);
}

std::string formatFixed(double value, int decimals) {
    return std::string(fixedText(value, decimals).view());
}

std::string formatShortest(double value) {
    return std::string(shortestText(value).view());
}

NumberText trimmedText(double value, int maxDecimals) {
    NumberText text = fixedText(value, maxDecimals);
    if (text.view().find('.') != std::string_view::npos) {
        while (text.chars[text.size - 1] == '0') {
            --text.size;
        }
        if (text.chars[text.size - 1] == '.') {
            --text.size;
        }
    }
    if (text.view() == "-0") {
        text.chars[0] = '0';
        text.size = 1;
    }
    return text;
}

std::string formatTrimmed(double value, int maxDecimals) {
    return std::string(trimmedText(value, maxDecimals).view());
}

} // namespace bladeaxis

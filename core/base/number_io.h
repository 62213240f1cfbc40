#pragma once
// Locale-independent number parsing and formatting for every file BladeAxis reads or writes.
// A decimal-comma desktop locale must never change a file (docs/architecture.md, Conventions), so
// nothing here uses iostreams, printf or strtod.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis {

// Parses a whole token as a decimal number ("12", "-0.5", ".5", "5.", "+3", "1e-3").
// Returns nullopt for anything else, including NaN/inf spellings and trailing garbage.
std::optional<double> parseNumber(std::string_view token);

// A plain decimal at the start of `text`: an optional sign, then up to 15 digits with at most
// one point ("-12.5", ".5", "5."). Reading stops at the first other character (a second point,
// an exponent, anything) without judging it. `length` is 0 when there is no digit or there are
// more than 15: not a plain decimal (a plain struct rather than an optional, so that the
// compiler keeps it in registers in the scanner's loop).
//
// Nearly every number in an NC program is one of these. Up to 15 digits make an integer below
// 2^53, and the powers of ten up to 1e15 are doubles: both are exact, so their quotient is
// rounded once and is the correctly rounded value parseNumber (from_chars) gives, found several
// times faster. Inline, because it runs for every word of a program.
struct PlainDecimal {
    double value = 0.0;
    std::size_t length = 0;         // characters read, the sign included; 0: none
    std::size_t integerDigits = 0;  // before the point
    std::size_t fractionDigits = 0; // after it
    bool hasPoint = false;
    bool integerPartZero = false; // every digit before the point is 0, or there is none
};

inline constexpr std::size_t kMaxPlainDigits = 15;

// 10^k for k <= kMaxPlainDigits, each exactly a double: reading and formatting plain decimals
// divide or multiply by them with a single rounding.
inline constexpr std::array<double, kMaxPlainDigits + 1> kExactPowersOfTen{
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

inline PlainDecimal readPlainDecimal(std::string_view text) {
    const auto isDigitAt = [text](std::size_t i) {
        return i < text.size() && text[i] >= '0' && text[i] <= '9';
    };
    std::size_t i = 0;
    const bool negative = !text.empty() && text[0] == '-';
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        ++i;
    }
    // Digits beyond 15 wrap the mantissa; such a number is refused below, so it does not matter.
    std::uint64_t mantissa = 0;
    const std::size_t integerBegin = i;
    for (; isDigitAt(i); ++i) {
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
    }
    // One object, returned whole (no copy): the scanner reads its fields where they were written.
    PlainDecimal number;
    number.integerDigits = i - integerBegin;
    number.integerPartZero = mantissa == 0;
    if (i < text.size() && text[i] == '.') {
        number.hasPoint = true;
        const std::size_t fractionBegin = ++i;
        for (; isDigitAt(i); ++i) {
            mantissa = mantissa * 10 + static_cast<std::uint64_t>(text[i] - '0');
        }
        number.fractionDigits = i - fractionBegin;
    }
    const std::size_t digits = number.integerDigits + number.fractionDigits;
    const bool plain = digits > 0 && digits <= kMaxPlainDigits;
    // A whole number needs no division, whose latency the next word would wait for.
    const double magnitude =
        !plain ? 0.0
        : number.fractionDigits == 0
            ? static_cast<double>(mantissa)
            : static_cast<double>(mantissa) / kExactPowersOfTen[number.fractionDigits];
    number.value = negative ? -magnitude : magnitude;
    number.length = plain ? i : 0;
    return number;
}

// A formatted number in a buffer of its own: the writer formats one or more numbers per block
// and keeps only the few it writes, so the others cost no string.
struct NumberText {
    std::array<char, 64> chars; // the first `size` are written: no clearing per number
    std::size_t size = 0;
    // What parseNumber reads the text back as, when the formatting knows it without parsing.
    std::optional<double> value;
    std::string_view view() const { return {chars.data(), size}; }
};

// Fixed-point text with exactly `decimals` digits after the point, "-0.000" normalised to "0.000".
NumberText fixedText(double value, int decimals);
std::string formatFixed(double value, int decimals);

// Shortest text that reads back to exactly the same double ("0.1", "1e-09").
std::string formatShortest(double value);

// Fixed-point text with up to `maxDecimals` digits, trailing zeros and a trailing point removed.
NumberText trimmedText(double value, int maxDecimals);
std::string formatTrimmed(double value, int maxDecimals);

} // namespace bladeaxis

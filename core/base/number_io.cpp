#include "core/base/number_io.h"

#include <array>
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

std::string formatFixed(double value, int decimals) {
    std::array<char, 64> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                   std::chars_format::fixed, decimals);
    if (ec != std::errc{}) {
        return formatShortest(value);
    }
    std::string text(buffer.data(), end);
    // A value that rounds to zero is written without a sign: controllers and diffs prefer "0.000".
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) {
        text.erase(0, 1);
    }
    return text;
}

std::string formatShortest(double value) {
    std::array<char, 64> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    (void)ec; // 64 characters always suffice for the shortest form of a double
    return {buffer.data(), end};
}

std::string formatTrimmed(double value, int maxDecimals) {
    std::string text = formatFixed(value, maxDecimals);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') {
            text.pop_back();
        }
        if (text.back() == '.') {
            text.pop_back();
        }
    }
    if (text == "-0") {
        text = "0";
    }
    return text;
}

} // namespace bladeaxis

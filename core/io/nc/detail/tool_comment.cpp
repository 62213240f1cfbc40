#include "core/io/nc/detail/tool_comment.h"

#include "core/base/number_io.h"

#include <cctype>
#include <cmath>
#include <string>

namespace bladeaxis::io::nc::detail {

namespace {

// The number after "<key>=" where the key is a whole word ("D=" but not "ID=" or "TD="),
// spaces allowed around '='.
std::optional<double> valueOf(const std::string& upper, std::string_view key) {
    for (std::size_t at = upper.find(key); at != std::string::npos; at = upper.find(key, at + 1)) {
        const bool wordStart = at == 0 || !std::isalnum(static_cast<unsigned char>(upper[at - 1]));
        std::size_t next = at + key.size();
        while (next < upper.size() && upper[next] == ' ') {
            ++next;
        }
        if (!wordStart || next >= upper.size() || upper[next] != '=') {
            continue;
        }
        ++next;
        while (next < upper.size() && upper[next] == ' ') {
            ++next;
        }
        std::size_t end = next;
        while (end < upper.size() &&
               (std::isdigit(static_cast<unsigned char>(upper[end])) || upper[end] == '.' ||
                upper[end] == '+' || upper[end] == '-')) {
            ++end;
        }
        if (const auto value = parseNumber(std::string_view(upper).substr(next, end - next))) {
            return value;
        }
    }
    return std::nullopt;
}

} // namespace

bool ToolComment::isBallEnd() const {
    return diameter > 0.0 && std::abs(2.0 * cornerRadius - diameter) <= 1e-6 * diameter;
}

std::optional<ToolComment> toolInComment(std::string_view line) {
    const std::size_t comment = line.find_first_of("(;");
    if (comment == std::string_view::npos) {
        return std::nullopt;
    }
    std::string upper(line.substr(comment + 1));
    for (char& c : upper) {
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    const auto diameter = valueOf(upper, "D");
    const auto cornerRadius = valueOf(upper, "CR");
    if (diameter && cornerRadius) {
        if (!(*diameter > 0.0) || *cornerRadius < 0.0) {
            return std::nullopt;
        }
        return ToolComment{*diameter, *cornerRadius};
    }
    // BladeAxis's generator: "(ball end R=8 mm, ...)". "R=" alone is too common a key (a
    // Sinumerik R parameter, a fillet in a note) to be read without the word "ball".
    if (upper.find("BALL") == std::string::npos) {
        return std::nullopt;
    }
    const auto radius = valueOf(upper, "R");
    if (!radius || !(*radius > 0.0)) {
        return std::nullopt;
    }
    return ToolComment{2.0 * *radius, *radius};
}

} // namespace bladeaxis::io::nc::detail

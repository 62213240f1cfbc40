#include "core/base/nearest_name.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace bladeaxis {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] =
                std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0U : 1U)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

namespace {

bool equalIgnoringCase(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    });
}

} // namespace

std::optional<std::string_view> nearestName(std::string_view typed,
                                            std::span<const std::string_view> known) {
    // "z" for "Z" is one edit from "X" and "Y" too: the same letters win.
    if (const auto same = std::ranges::find_if(
            known, [typed](std::string_view name) { return equalIgnoringCase(typed, name); });
        same != known.end()) {
        return *same;
    }
    const auto nearest = std::ranges::min_element(
        known, {}, [typed](std::string_view candidate) { return editDistance(typed, candidate); });
    if (nearest == known.end() ||
        editDistance(typed, *nearest) > std::max<std::size_t>(2, typed.size() / 3)) {
        return std::nullopt;
    }
    return *nearest;
}

} // namespace bladeaxis

#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace bladeaxis {

// Edits (insertions, deletions, substitutions) that turn a into b.
std::size_t editDistance(std::string_view a, std::string_view b);

// The known name a mistyped one most likely meant: the nearest by edit distance, when it is
// within a third of the typed name's length (at least 2 edits), else none. Used for the
// "did you mean" of unknown keys, options and subcommands.
std::optional<std::string_view> nearestName(std::string_view typed,
                                            std::span<const std::string_view> known);

} // namespace bladeaxis

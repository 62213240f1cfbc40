#pragma once

#include <span>
#include <string>
#include <string_view>

namespace bladeaxis {

// The line (1-based) of the key at `path` in a JSON text, e.g. {"axes", "Z", "max_mm"}; an
// array element's segment is its index ("0"). 0 when the path is not in the text. The text
// must be valid JSON (parse it first). nlohmann::json keeps no positions, and searching for
// the key's first quoted occurrence named the X axis's "max_mm" for an error in Z's.
// With a key given twice the last one counts, as nlohmann keeps the last value.
int lineOfJsonKey(std::string_view text, std::span<const std::string> path);

// A key path as a file's reader names it: "axes.Z.max_mm", an array element's index in
// brackets ("layer_edits[2].preset").
std::string jsonKeyPathText(std::span<const std::string> path);

} // namespace bladeaxis

#pragma once
// Reading inputs whole and writing outputs atomically: a failed write never leaves a partial
// file, and an output path that names an input is refused, so inputs are never changed.

#include "core/base/error.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace bladeaxis {

// Reads a whole file as bytes. Errors: FileNotFound, FileUnreadable (also for directories).
Result<std::string> readTextFile(const std::filesystem::path& path);

// Writes `content` to a temporary file beside `path`, flushes it and renames it over `path`.
// Refuses (WriteFailed) when `path` is the same file as any of `protectedInputs`.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                           std::span<const std::filesystem::path> protectedInputs = {});

// True when both paths name the same existing file (after resolving links).
bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace bladeaxis

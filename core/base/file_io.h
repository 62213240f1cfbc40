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

// Writes `content` so that `path` holds either its old content or the whole new one, never a
// part, even when the process is killed or the disk fills up:
// - a regular file (or a new name) is written to an unnamed temporary file in the same folder
//   (O_TMPFILE; a named `.name.tmpN` sibling where the file system lacks it), synced, given the
//   old file's permission bits, renamed over `path`, and the folder synced;
// - a symbolic link is followed: its target is replaced as above and the link stays a link;
// - a character device or a pipe (`/dev/stdout`, a FIFO) is written directly: it holds no old
//   content to protect and renaming over it would replace the device with a file;
// - anything else (a folder, a socket, a block device) is refused.
// Refuses (WriteFailed) when `path` is, or links to, the same file as any of `protectedInputs`
// (also through hard links). Errors name the path and the system's reason.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                           std::span<const std::filesystem::path> protectedInputs = {});

// True when both paths name the same existing file (after resolving links).
bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace bladeaxis

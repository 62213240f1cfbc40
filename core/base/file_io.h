#pragma once
// Reading inputs whole and writing outputs atomically: a failed write never leaves a partial
// file, and an output path that names an input is refused, so inputs are never changed.

#include "core/base/error.h"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace bladeaxis {

// Reads a whole file as bytes. Errors: FileNotFound, FileUnreadable (also for directories).
Result<std::string> readTextFile(const std::filesystem::path& path);

// Writes `content` so that `path` holds either its old content or the whole new one, never a
// part, even when the process is killed or the disk fills up:
// - a regular file (or a new name) is written to an unnamed temporary file in the same folder
//   (O_TMPFILE; a named `.ba-XXXXXX` sibling where the file system lacks it), synced, given the
//   old file's permission bits, renamed over `path`, and the folder synced;
// - a symbolic link is followed: its target is replaced as above and the link stays a link;
// - a character device or a pipe (`/dev/stdout`, a FIFO) is written directly: it holds no old
//   content to protect and renaming over it would replace the device with a file;
// - anything else (a folder, a socket, a block device) is refused.
// Refuses (WriteFailed) when `path` is, or links to, the same file as any of `protectedInputs`
// (also through hard links). Errors name the path and the system's reason.
Status writeFileAtomically(const std::filesystem::path& path, std::string_view content,
                           std::span<const std::filesystem::path> protectedInputs = {});

// A file's bytes mapped read-only, for reading a large file once from start to end: pages read
// are in the resident set until releaseBefore() gives them back (the file keeps them).
class MappedText {
  public:
    MappedText() = default;
    MappedText(const char* data, std::size_t size);
    MappedText(MappedText&&) noexcept;
    MappedText& operator=(MappedText&&) noexcept;
    MappedText(const MappedText&) = delete;
    MappedText& operator=(const MappedText&) = delete;
    ~MappedText();

    std::string_view text() const { return {m_data, m_size}; }
    // Takes the whole pages before `offset` out of the resident set; read again, they come back
    // from the file with the same bytes.
    void releaseBefore(std::size_t offset) const;

  private:
    const char* m_data = nullptr;
    std::size_t m_size = 0;
    mutable std::size_t m_released = 0; // bytes from the start already given back
};

// The content of a regular file written in pieces before it is given its name: it is an
// unnamed temporary file in the target's folder (a `.ba-XXXXXX` sibling where the file system
// cannot make one unnamed) until commit() moves it over the target exactly as
// writeFileAtomically does. Dropped uncommitted, nothing of it remains, also when the process is
// killed (an unnamed file). A job writes a large output here while it runs instead of holding
// it in memory, and reads it back from here (mapText).
// The file a path finally names: a symbolic link (or a chain of them, up to 40) is replaced by
// its target, relative targets resolved against the link's folder; a dangling link names the
// file a write through it would create.
std::filesystem::path followLinks(std::filesystem::path path);

class StagedFile {
  public:
    // Refuses (WriteFailed) what writeFileAtomically refuses, and a target that is not a regular
    // file or a new name (a pipe or a device cannot be staged: see isStageable).
    static Result<StagedFile> open(const std::filesystem::path& path,
                                   std::span<const std::filesystem::path> protectedInputs = {});
    // True when `path` (after following links) is a regular file or a new name in an existing
    // folder.
    static bool isStageable(const std::filesystem::path& path);

    StagedFile(StagedFile&&) noexcept;
    StagedFile& operator=(StagedFile&&) noexcept;
    ~StagedFile();

    Status append(std::string_view content);
    std::size_t size() const;
    const std::filesystem::path& target() const;
    // The file the content replaces: target() with its links followed.
    const std::filesystem::path& resolvedTarget() const;
    // Syncs the content and moves it over the target. Once committed the file stays readable
    // here; a second commit names it again (the same bytes).
    Status commit();

    // The content written so far, mapped read-only; see MappedText.
    Result<MappedText> mapText() const;

  private:
    struct State;
    explicit StagedFile(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

// True when both paths name the same existing file (after resolving links).
bool isSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

// True when writing to `a` and to `b` would write the same file: the same existing file (also
// through links and hard links), or, for a name not yet there, the same place once links in its
// folders are followed. A character device or a pipe (`/dev/null`, a FIFO) holds nothing a
// second write could replace and is never the same.
bool isSameDestination(const std::filesystem::path& a, const std::filesystem::path& b);

// True when `path` holds a NUL character: the system reads a path up to its first NUL, so
// "victim.json\0.nc" would name victim.json.
bool hasNulCharacter(const std::filesystem::path& path);

// A fresh name for a temporary file in `folder`: `.ba-` and six random letters or digits. Its
// length does not depend on the target's, so a target with the longest name a file system
// allows (255 bytes) can still be written through a temporary beside it.
std::filesystem::path temporaryNameIn(const std::filesystem::path& folder);

} // namespace bladeaxis

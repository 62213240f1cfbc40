#pragma once
// A text read once from its start to its end: from memory, or read again from the file it was
// first read from, a few megabytes at a time. A large program's text then need not stay in
// memory between its parse and its rewrite, and the file must be the one that was parsed.

#include "core/base/descriptor.h"
#include "core/base/error.h"

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <sys/types.h>

namespace bladeaxis {

// What the file system tells of a file's content: a file written again or replaced since has
// another size, modification time (to the nanosecond) or inode.
struct FileSnapshot {
    std::filesystem::path path;
    dev_t device = 0;
    ino_t inode = 0;
    off_t size = 0;
    timespec modified{};

    bool sameFileAs(const FileSnapshot& other) const;
};

// FileNotFound / FileUnreadable.
Result<FileSnapshot> snapshotOf(const std::filesystem::path& path);

class ForwardText {
  public:
    // A text in memory, which must outlive this.
    explicit ForwardText(std::string_view whole);
    // The file of `snapshot`, refused (FileUnreadable) when it is no longer that file: a text
    // parsed from it must not be rewritten from another.
    static Result<ForwardText> reopen(const FileSnapshot& snapshot);

    std::size_t size() const { return m_size; }

    // The bytes [begin, end) (end at most size()). Empty with failure() set when the file
    // cannot give them (it was cut short since it was read).
    std::string_view range(std::size_t begin, std::size_t end);
    // The line starting at `begin`, without its line feed and carriage return.
    std::string_view lineFrom(std::size_t begin);
    // Nothing before `offset` is asked for again: a file's window lets it go.
    void releaseBefore(std::size_t offset) { m_released = std::max(m_released, offset); }

    const std::optional<Error>& failure() const { return m_failure; }

  private:
    ForwardText(Descriptor file, std::size_t size, std::filesystem::path path);
    bool load(std::size_t end);

    std::string_view m_memory; // the whole text, when in memory
    Descriptor m_file;         // the file, when read again from it
    std::size_t m_size = 0;
    std::filesystem::path m_path;
    std::string m_window;          // the file's bytes from m_windowBegin
    std::size_t m_windowBegin = 0; // offset of m_window[0]
    std::size_t m_released = 0;
    std::optional<Error> m_failure;
};

} // namespace bladeaxis

#pragma once
// The outputs of one run, published all or none: a job that cannot write one of its files
// (a report folder that is not writable, a bad CL path) must not leave the others on disk as
// though it had finished.

#include "core/base/file_io.h"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis {

// Every file is staged (written whole beside its target, see StagedFile) before any is moved
// into place, so a destination that cannot take its file (a folder in its place, a missing
// folder, a full disk) fails the set while nothing is published yet. publish() then moves them
// all; when one move fails, those already moved are undone (a replaced file gets its old content
// back, a new one is removed). A character device or a pipe (`/dev/null`, a FIFO) holds nothing
// to undo and is written last, directly. Dropped unpublished, nothing of the set remains.
class OutputSet {
  public:
    explicit OutputSet(std::vector<std::filesystem::path> protectedInputs = {});
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    ~OutputSet();

    // Stages `content` for `path`; refuses what writeFileAtomically refuses (an input, a folder).
    Status add(const std::filesystem::path& path, std::string_view content);
    // A file a job staged while it ran (the re-scheduled program).
    void adopt(std::shared_ptr<StagedFile> staged);
    // Moves every staged file into place, then writes the devices; all or none on failure.
    Status publish();

  private:
    struct Published;
    Status publishStaged(std::vector<Published>& done);

    std::vector<std::filesystem::path> m_inputs;
    std::vector<std::shared_ptr<StagedFile>> m_staged;
    std::vector<std::pair<std::filesystem::path, std::string>> m_devices;
};

// Creates `folder` (and its missing parents) for a run's outputs and removes what it created
// when dropped, unless keep() was called: a failed run leaves no empty folder of its own behind.
// An empty path makes nothing.
class CreatedFolder {
  public:
    static Result<CreatedFolder> create(const std::filesystem::path& folder);
    CreatedFolder(CreatedFolder&&) noexcept;
    CreatedFolder& operator=(CreatedFolder&&) = delete;
    CreatedFolder(const CreatedFolder&) = delete;
    CreatedFolder& operator=(const CreatedFolder&) = delete;
    ~CreatedFolder();
    void keep() { m_created.clear(); }

  private:
    CreatedFolder() = default;
    std::vector<std::filesystem::path> m_created; // deepest first
};

// A path with the name a message gives it ("-o", "output_program", "--out (report.json)").
struct NamedPath {
    std::string name;
    std::filesystem::path path;
};

// Refuses (InvalidArgument, naming both) two outputs that are the same destination
// (isSameDestination), or an output that is one of the inputs; and any path with a NUL
// character. Empty paths and "-" (standard input or output) are left out.
Status refuseSharedFiles(std::span<const NamedPath> outputs, std::span<const NamedPath> inputs);

} // namespace bladeaxis

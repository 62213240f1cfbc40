#include "core/base/output_set.h"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace bladeaxis {

namespace fs = std::filesystem;

namespace {

Status failure(const fs::path& path, const std::string& what) {
    return makeError(ErrorCode::WriteFailed, what, {path.string()});
}

bool isRegularFile(const fs::path& path) {
    struct stat existing {};
    return ::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
}

// A second name for the file `target` names now, so that its content can be put back if the
// set is undone; empty when the file system has no hard links (the old content is then lost
// on publish, as with a single atomic write).
fs::path keepOldContent(const fs::path& target) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    for (int attempt = 0; attempt < 16; ++attempt) {
        const fs::path backup = temporaryNameIn(folder);
        if (::link(target.c_str(), backup.c_str()) == 0) {
            return backup;
        }
        if (errno != EEXIST) {
            break;
        }
    }
    return {};
}

} // namespace

// A file moved into place: what it replaced (a second name of the old content), or nothing
// when it was new.
struct OutputSet::Published {
    fs::path target;
    fs::path backup;
    bool existed = false;
};

OutputSet::OutputSet(std::vector<fs::path> protectedInputs)
    : m_inputs(std::move(protectedInputs)) {}

OutputSet::~OutputSet() = default;

Status OutputSet::add(const fs::path& path, std::string_view content) {
    if (StagedFile::isStageable(path)) {
        auto staged = StagedFile::open(path, m_inputs);
        if (!staged) {
            return std::unexpected(staged.error());
        }
        if (auto written = staged->append(content); !written) {
            return written;
        }
        m_staged.push_back(std::make_shared<StagedFile>(std::move(*staged)));
        return {};
    }
    // Not a regular file nor a new name in an existing folder: a device or a pipe is written at
    // the end; anything else (a folder, a missing folder) is refused here, before any is written.
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0 &&
        (S_ISCHR(existing.st_mode) || S_ISFIFO(existing.st_mode))) {
        m_devices.emplace_back(path, std::string(content));
        return {};
    }
    if (::stat(path.c_str(), &existing) == 0) {
        return failure(path, S_ISDIR(existing.st_mode)
                                 ? "is a folder, expected a file name"
                                 : "is neither a regular file, a character device nor a pipe");
    }
    return failure(path, std::string("cannot write here: ") + std::strerror(errno));
}

void OutputSet::adopt(std::shared_ptr<StagedFile> staged) {
    m_staged.push_back(std::move(staged));
}

Status OutputSet::publishStaged(std::vector<Published>& done) {
    for (const std::shared_ptr<StagedFile>& staged : m_staged) {
        Published entry{staged->resolvedTarget(), {}, isRegularFile(staged->resolvedTarget())};
        if (entry.existed) {
            entry.backup = keepOldContent(entry.target);
        }
        if (auto committed = staged->commit(); !committed) {
            if (!entry.backup.empty()) {
                ::unlink(entry.backup.c_str());
            }
            return committed;
        }
        done.push_back(std::move(entry));
    }
    return {};
}

Status OutputSet::publish() {
    std::vector<Published> done;
    Status status = publishStaged(done);
    for (auto device = m_devices.begin(); status && device != m_devices.end(); ++device) {
        status = writeFileAtomically(device->first, device->second, m_inputs);
    }
    // Undone newest first; a file that replaced one without a second name stays (see above).
    for (auto entry = done.rbegin(); entry != done.rend(); ++entry) {
        if (status) {
            if (!entry->backup.empty()) {
                ::unlink(entry->backup.c_str());
            }
        } else if (!entry->backup.empty()) {
            ::rename(entry->backup.c_str(), entry->target.c_str());
        } else if (!entry->existed) {
            ::unlink(entry->target.c_str());
        }
    }
    return status;
}

Result<CreatedFolder> CreatedFolder::create(const fs::path& folder) {
    CreatedFolder created;
    if (folder.empty()) {
        return created; // no output folder: nothing to make
    }
    std::error_code ec;
    fs::path start = fs::absolute(folder, ec).lexically_normal();
    if (!start.has_filename()) { // "out/": its parent is "out" itself
        start = start.parent_path();
    }
    for (fs::path missing = start; !missing.empty() && !fs::exists(fs::symlink_status(missing, ec));
         missing = missing.parent_path()) {
        created.m_created.push_back(missing);
        if (missing == missing.parent_path()) {
            break;
        }
    }
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(folder)) {
        // What it made of the path before failing is removed with `created`.
        return makeError(ErrorCode::WriteFailed,
                         "cannot create the output folder: " +
                             (ec ? ec.message() : std::string("a file of that name is there")),
                         {folder.string()});
    }
    return created;
}

CreatedFolder::CreatedFolder(CreatedFolder&& other) noexcept
    : m_created(std::move(other.m_created)) {
    other.m_created.clear();
}

CreatedFolder::~CreatedFolder() {
    for (const fs::path& folder : m_created) {
        std::error_code ec;
        fs::remove(folder, ec); // only when empty: a folder that holds anything is not removed
    }
}

namespace {

bool isNamed(const NamedPath& named) {
    return !named.path.empty() && named.path != "-";
}

Status sharedFile(const NamedPath& first, const NamedPath& second, const std::string& why) {
    return makeError(ErrorCode::InvalidArgument, first.name + " and " + second.name +
                                                     " name the same file " + second.path.string() +
                                                     ": " + why);
}

} // namespace

Status refuseSharedFiles(std::span<const NamedPath> outputs, std::span<const NamedPath> inputs) {
    for (const auto* list : {&outputs, &inputs}) {
        for (const NamedPath& named : *list) {
            if (hasNulCharacter(named.path)) {
                return makeError(ErrorCode::InvalidArgument,
                                 named.name + ": a path with a NUL character, which the system "
                                              "would cut short at the NUL");
            }
        }
    }
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        if (!isNamed(outputs[i])) {
            continue;
        }
        for (const NamedPath& input : inputs) {
            if (isNamed(input) && isSameDestination(outputs[i].path, input.path)) {
                return sharedFile(outputs[i], input, "the output would overwrite the input");
            }
        }
        for (std::size_t j = i + 1; j < outputs.size(); ++j) {
            if (isNamed(outputs[j]) && isSameDestination(outputs[i].path, outputs[j].path)) {
                return sharedFile(outputs[i], outputs[j], "one output would overwrite the other");
            }
        }
    }
    return {};
}

} // namespace bladeaxis

#include "core/base/file_io.h"

#include "core/base/descriptor.h"
#include "core/base/memory_policy.h"
#include "core/base/pages_mapped_ahead.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <optional>
#include <random>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace bladeaxis {

namespace fs = std::filesystem;

Result<std::string> readTextFile(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        return makeError(ErrorCode::FileNotFound, "no such file", {path.string()});
    }
    if (fs::is_directory(path, ec)) {
        return makeError(ErrorCode::FileUnreadable, "is a directory, expected a file",
                         {path.string()});
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return makeError(ErrorCode::FileUnreadable,
                         std::string("cannot open for reading: ") + std::strerror(errno),
                         {path.string()});
    }
    std::string content;
    in.seekg(0, std::ios::end);
    const auto size = in.tellg();
    if (size > 0) {
        in.seekg(0, std::ios::beg);
        // Read straight into the string's fresh memory, not over zeros written first (a
        // 320 MB program's text is written once instead of twice); a file that shrank since
        // its size was taken gives what it still has. The back half's pages are mapped on the
        // other core while the front half is read (PagesMappedAhead).
        content.resize_and_overwrite(
            static_cast<std::size_t>(size), [&in](char* data, std::size_t bytes) {
                const PagesMappedAhead backHalf({{data + bytes / 2, bytes - bytes / 2}});
                in.read(data, static_cast<std::streamsize>(bytes));
                return static_cast<std::size_t>(in.gcount());
            });
    }
    if (!in && !in.eof()) {
        return makeError(ErrorCode::FileUnreadable, "read failed", {path.string()});
    }
    return content;
}

bool hasNulCharacter(const fs::path& path) {
    return path.native().find('\0') != std::string::npos;
}

namespace {

// Where a path ends up once every link on the way is followed; a name not yet there keeps its
// own last part under its folder's resolved place.
fs::path resolvedPlace(const fs::path& path) {
    std::error_code ec;
    return fs::weakly_canonical(fs::absolute(followLinks(path), ec).lexically_normal(), ec);
}

} // namespace

bool isSameDestination(const fs::path& a, const fs::path& b) {
    struct stat first {};
    struct stat second {};
    const bool firstExists = ::stat(a.c_str(), &first) == 0;
    const bool secondExists = ::stat(b.c_str(), &second) == 0;
    if (firstExists && secondExists) {
        const auto stream = [](const struct stat& s) {
            return S_ISCHR(s.st_mode) || S_ISFIFO(s.st_mode);
        };
        return !stream(first) && first.st_dev == second.st_dev && first.st_ino == second.st_ino;
    }
    return firstExists == secondExists && resolvedPlace(a) == resolvedPlace(b);
}

fs::path temporaryNameIn(const fs::path& folder) {
    static constexpr std::string_view kLetters =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    std::random_device device;
    std::string name = ".ba-";
    for (int i = 0; i < 6; ++i) {
        name += kLetters[device() % kLetters.size()];
    }
    return folder / name;
}

bool isSameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

namespace {

// The system's reason for the last failed call, for messages.
std::string reason() {
    return std::strerror(errno);
}

Status failure(const fs::path& path, const std::string& what) {
    return makeError(ErrorCode::WriteFailed, what, {path.string()});
}

// Writes every byte, resuming after short writes and signals.
bool writeAll(int fd, std::string_view content) {
    while (!content.empty()) {
        const ssize_t written = ::write(fd, content.data(), content.size());
        if (written < 0) {
            if (errno == EINTR) {
                continue;
            }
            return false;
        }
        content.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

Status writeDirectly(const fs::path& path, std::string_view content) {
    Descriptor fd(::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC));
    if (!fd.valid()) {
        return failure(path, "cannot open for writing: " + reason());
    }
    if (!writeAll(fd.get(), content) || !fd.close()) {
        return failure(path, "write failed: " + reason());
    }
    return {};
}

fs::path folderOf(const fs::path& path) {
    return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// Why a write into the new content failed, in the words a user acts on.
std::string writeFailure() {
    return errno == ENOSPC || errno == EFBIG || errno == EDQUOT
               ? "the disk is full or the file too large: " + reason()
               : "write failed: " + reason();
}

// A descriptor for the new content: unnamed when the file system supports it, so that a killed
// process leaves nothing behind; `named` is set to the sibling's name otherwise.
int openTemporary(const fs::path& path, mode_t mode, fs::path& named) {
    const int fd = ::open(folderOf(path).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, mode);
    if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) {
        return fd;
    }
    for (int attempt = 0; attempt < 16; ++attempt) {
        named = temporaryNameIn(folderOf(path));
        const int sibling = ::open(named.c_str(), O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC, mode);
        if (sibling >= 0 || errno != EEXIST) {
            return sibling;
        }
    }
    return -1;
}

// Gives an unnamed temporary file a name beside `path`: linkat cannot replace, so it gets a
// fresh sibling name that the rename then moves over `path`.
bool nameTemporary(int fd, const fs::path& path, fs::path& named) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    for (int attempt = 0; attempt < 16; ++attempt) {
        named = temporaryNameIn(folderOf(path));
        if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, named.c_str(), AT_SYMLINK_FOLLOW) == 0) {
            return true;
        }
        if (errno != EEXIST) {
            return false;
        }
    }
    return false;
}

void syncFolder(const fs::path& path) {
    Descriptor folder(::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (folder.valid()) {
        ::fsync(folder.get()); // best effort: some file systems refuse it on folders
    }
}

Status refuseInputs(const fs::path& path, std::span<const fs::path> protectedInputs) {
    for (const fs::path& input : protectedInputs) {
        if (isSameFile(path, input)) {
            return makeError(ErrorCode::WriteFailed,
                             "refusing to overwrite the input file " + input.string(),
                             {path.string()});
        }
    }
    return {};
}

// The permission bits a replaced file keeps, or a new file's under the umask; nothing when the
// path (resolved by the kernel, through every link) is neither a regular file nor a new name.
std::optional<mode_t> stagedMode(const fs::path& path) {
    struct stat existing {};
    if (::stat(path.c_str(), &existing) != 0) {
        if (errno != ENOENT) {
            return std::nullopt;
        }
        const mode_t umaskValue = ::umask(0);
        ::umask(umaskValue);
        return 0666 & ~umaskValue;
    }
    if (!S_ISREG(existing.st_mode)) {
        return std::nullopt;
    }
    return existing.st_mode & 07777;
}

Status replaceRegularFile(const fs::path& path, std::string_view content) {
    auto staged = StagedFile::open(path);
    if (!staged) {
        return std::unexpected(staged.error());
    }
    if (auto written = staged->append(content); !written) {
        return written;
    }
    return staged->commit();
}

} // namespace

// The file a path finally names: a symbolic link (or a chain of them) is replaced by its target,
// relative targets resolved against the link's folder.
fs::path followLinks(fs::path path) {
    for (int depth = 0; depth < 40; ++depth) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(path, ec))) {
            return path;
        }
        const fs::path target = fs::read_symlink(path, ec);
        if (ec) {
            return path;
        }
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    return path; // a loop: the open below reports it
}

Status writeFileAtomically(const fs::path& path, std::string_view content,
                           std::span<const fs::path> protectedInputs) {
    if (auto refused = refuseInputs(path, protectedInputs); !refused) {
        return refused;
    }
    // What the path names as the kernel resolves it: /dev/stdout on a pipe is a link to
    // "pipe:[N]", which names no file when read as a path.
    struct stat existing {};
    if (::stat(path.c_str(), &existing) != 0) {
        if (errno != ENOENT) {
            return failure(path, "cannot write here: " + reason());
        }
        return replaceRegularFile(path, content);
    }
    if (S_ISREG(existing.st_mode)) {
        return replaceRegularFile(path, content);
    }
    if (S_ISCHR(existing.st_mode) || S_ISFIFO(existing.st_mode)) {
        return writeDirectly(path, content);
    }
    return failure(path, S_ISDIR(existing.st_mode)
                             ? "is a folder, expected a file name"
                             : "is neither a regular file, a character device nor a pipe");
}

struct StagedFile::State {
    State(fs::path requestedPath, fs::path targetPath, fs::path sibling, int descriptor)
        : requested(std::move(requestedPath)), target(std::move(targetPath)),
          named(std::move(sibling)), fd(descriptor) {}
    State(const State&) = delete;
    State& operator=(const State&) = delete;
    ~State() {
        if (!committed && !named.empty()) {
            ::unlink(named.c_str());
        }
    }

    fs::path requested; // the path as given, for messages
    fs::path target;    // the file the content replaces (links followed)
    fs::path named;     // the content's sibling name while it has one (no unnamed files)
    Descriptor fd;
    std::size_t size = 0;
    bool committed = false;
};

StagedFile::StagedFile(std::unique_ptr<State> state) : m_state(std::move(state)) {}
StagedFile::StagedFile(StagedFile&&) noexcept = default;
StagedFile& StagedFile::operator=(StagedFile&&) noexcept = default;
StagedFile::~StagedFile() = default;

bool StagedFile::isStageable(const fs::path& path) {
    std::error_code ec;
    return fs::is_directory(folderOf(followLinks(path)), ec) && stagedMode(path).has_value();
}

Result<StagedFile> StagedFile::open(const fs::path& path,
                                    std::span<const fs::path> protectedInputs) {
    if (auto refused = refuseInputs(path, protectedInputs); !refused) {
        return std::unexpected(refused.error());
    }
    const fs::path target = followLinks(path);
    struct stat existing {};
    if (::stat(path.c_str(), &existing) != 0 && errno != ENOENT) {
        return std::unexpected(failure(path, "cannot write here: " + reason()).error());
    }
    const std::optional<mode_t> mode = stagedMode(path);
    if (!mode) {
        return std::unexpected(
            failure(path, "is neither a regular file nor a new name: a folder, a pipe or a "
                          "device cannot hold a file written in pieces")
                .error());
    }
    fs::path named;
    const int fd = openTemporary(target, *mode, named);
    if (fd < 0) {
        return std::unexpected(failure(path, "cannot create the output in " +
                                                 folderOf(target).string() + ": " + reason())
                                   .error());
    }
    auto state = std::make_unique<State>(path, target, std::move(named), fd);
    // The permission bits of the file replaced (open applied the umask to a new one).
    if (::fchmod(state->fd.get(), *mode) != 0) {
        return std::unexpected(failure(path, "write failed: " + reason()).error());
    }
    return StagedFile(std::move(state));
}

Status StagedFile::append(std::string_view content) {
    if (!writeAll(m_state->fd.get(), content)) {
        return failure(m_state->requested, writeFailure());
    }
    m_state->size += content.size();
    return {};
}

std::size_t StagedFile::size() const {
    return m_state->size;
}

const fs::path& StagedFile::target() const {
    return m_state->requested;
}

const fs::path& StagedFile::resolvedTarget() const {
    return m_state->target;
}

Status StagedFile::commit() {
    State& state = *m_state;
    if (::fsync(state.fd.get()) != 0) {
        return failure(state.requested, writeFailure());
    }
    struct stat content {};
    struct stat current {};
    if (state.committed && ::fstat(state.fd.get(), &content) == 0 &&
        ::stat(state.target.c_str(), &current) == 0 && content.st_dev == current.st_dev &&
        content.st_ino == current.st_ino) {
        return {}; // already there
    }
    if (state.named.empty() && !nameTemporary(state.fd.get(), state.target, state.named)) {
        return failure(state.requested, "cannot name the new output: " + reason());
    }
    if (::rename(state.named.c_str(), state.target.c_str()) != 0) {
        const std::string why = reason();
        ::unlink(state.named.c_str()); // the descriptor keeps the content
        state.named.clear();
        return failure(state.requested, "cannot move the new output into place: " + why);
    }
    state.named.clear();
    state.committed = true;
    syncFolder(state.target);
    return {};
}

Result<MappedText> StagedFile::mapText() const {
    if (m_state->size == 0) {
        return MappedText();
    }
    void* data = ::mmap(nullptr, m_state->size, PROT_READ, MAP_SHARED, m_state->fd.get(), 0);
    if (data == MAP_FAILED) {
        return makeError(ErrorCode::FileUnreadable,
                         "cannot read the staged output back: " + reason(),
                         {m_state->requested.string()});
    }
    return MappedText(static_cast<const char*>(data), m_state->size);
}

MappedText::MappedText(const char* data, std::size_t size) : m_data(data), m_size(size) {}

MappedText::MappedText(MappedText&& other) noexcept
    : m_data(std::exchange(other.m_data, nullptr)), m_size(std::exchange(other.m_size, 0)),
      m_released(std::exchange(other.m_released, 0)) {}

MappedText& MappedText::operator=(MappedText&& other) noexcept {
    if (this != &other) {
        this->~MappedText();
        m_data = std::exchange(other.m_data, nullptr);
        m_size = std::exchange(other.m_size, 0);
        m_released = std::exchange(other.m_released, 0);
    }
    return *this;
}

MappedText::~MappedText() {
    if (m_data != nullptr) {
        ::munmap(const_cast<char*>(m_data), m_size);
        m_data = nullptr;
    }
}

void MappedText::releaseBefore(std::size_t offset) const {
    const std::size_t end = std::min(offset, m_size);
    if (m_data == nullptr || end <= m_released) {
        return;
    }
    // The mapping starts on a page and what was given back ends on one, so the pages from
    // m_released on are whole.
    m_released +=
        returnWholePagesToTheSystem(const_cast<char*>(m_data) + m_released, end - m_released);
}

} // namespace bladeaxis

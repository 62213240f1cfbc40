#include "core/base/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

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
        content.resize(static_cast<std::size_t>(size));
        in.seekg(0, std::ios::beg);
        in.read(content.data(), static_cast<std::streamsize>(content.size()));
    }
    if (!in && !in.eof()) {
        return makeError(ErrorCode::FileUnreadable, "read failed", {path.string()});
    }
    return content;
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

// Closes a descriptor when it goes out of scope.
class Descriptor {
  public:
    explicit Descriptor(int fd) : m_fd(fd) {}
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() {
        if (m_fd >= 0) {
            ::close(m_fd);
        }
    }
    int get() const { return m_fd; }
    bool valid() const { return m_fd >= 0; }
    // Closes now, reporting the close's own failure (NFS reports write errors here).
    bool close() {
        const int fd = m_fd;
        m_fd = -1;
        return ::close(fd) == 0;
    }

  private:
    int m_fd;
};

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

// A descriptor for the new content: unnamed when the file system supports it, so that a killed
// process leaves nothing behind; `named` is set to the sibling's name otherwise.
int openTemporary(const fs::path& path, mode_t mode, fs::path& named) {
    const int fd = ::open(folderOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
    if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) {
        return fd;
    }
    std::random_device device;
    for (int attempt = 0; attempt < 16; ++attempt) {
        named =
            folderOf(path) / ("." + path.filename().string() + ".tmp" + std::to_string(device()));
        const int sibling = ::open(named.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, mode);
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
    std::random_device device;
    for (int attempt = 0; attempt < 16; ++attempt) {
        named =
            folderOf(path) / ("." + path.filename().string() + ".tmp" + std::to_string(device()));
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

Status replaceRegularFile(const fs::path& path, std::string_view content, mode_t mode) {
    fs::path named;
    Descriptor fd(openTemporary(path, mode, named));
    if (!fd.valid()) {
        return failure(path,
                       "cannot create the output in " + folderOf(path).string() + ": " + reason());
    }
    const auto discard = [&named] {
        if (!named.empty()) {
            ::unlink(named.c_str());
        }
    };
    // The permission bits of the file replaced (open applied the umask to a new one).
    if (::fchmod(fd.get(), mode) != 0 || !writeAll(fd.get(), content) || ::fsync(fd.get()) != 0) {
        const std::string why = errno == ENOSPC || errno == EFBIG || errno == EDQUOT
                                    ? "the disk is full or the file too large: " + reason()
                                    : "write failed: " + reason();
        discard();
        return failure(path, why);
    }
    if (named.empty() && !nameTemporary(fd.get(), path, named)) {
        return failure(path, "cannot name the new output: " + reason());
    }
    if (!fd.close()) {
        discard();
        return failure(path, "write failed: " + reason());
    }
    if (::rename(named.c_str(), path.c_str()) != 0) {
        const std::string why = reason();
        discard();
        return failure(path, "cannot move the new output into place: " + why);
    }
    syncFolder(path);
    return {};
}

} // namespace

Status writeFileAtomically(const fs::path& path, std::string_view content,
                           std::span<const fs::path> protectedInputs) {
    for (const fs::path& input : protectedInputs) {
        if (isSameFile(path, input)) {
            return makeError(ErrorCode::WriteFailed,
                             "refusing to overwrite the input file " + input.string(),
                             {path.string()});
        }
    }
    const fs::path target = followLinks(path);
    struct stat existing {};
    if (::stat(target.c_str(), &existing) != 0) {
        if (errno != ENOENT) {
            return failure(path, "cannot write here: " + reason());
        }
        const mode_t umaskValue = ::umask(0);
        ::umask(umaskValue);
        return replaceRegularFile(target, content, 0666 & ~umaskValue);
    }
    if (S_ISREG(existing.st_mode)) {
        return replaceRegularFile(target, content, existing.st_mode & 07777);
    }
    if (S_ISCHR(existing.st_mode) || S_ISFIFO(existing.st_mode)) {
        return writeDirectly(target, content);
    }
    return failure(path, S_ISDIR(existing.st_mode)
                             ? "is a folder, expected a file name"
                             : "is neither a regular file, a character device nor a pipe");
}

} // namespace bladeaxis

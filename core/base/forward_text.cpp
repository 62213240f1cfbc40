#include "core/base/forward_text.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace bladeaxis {

namespace {

// A window holds at least this much of the file beyond what was asked for: one read per few
// megabytes, and the window is about this large.
constexpr std::size_t kWindowBytes = std::size_t{4} << 20;

FileSnapshot snapshotFrom(const std::filesystem::path& path, const struct stat& status) {
    return {path, status.st_dev, status.st_ino, status.st_size, status.st_mtim};
}

Error unreadable(const std::filesystem::path& path, const std::string& what) {
    return Error{ErrorCode::FileUnreadable, what, {path.string(), 0, 0}, {}};
}

} // namespace

bool FileSnapshot::sameFileAs(const FileSnapshot& other) const {
    return device == other.device && inode == other.inode && size == other.size &&
           modified.tv_sec == other.modified.tv_sec && modified.tv_nsec == other.modified.tv_nsec;
}

Result<FileSnapshot> snapshotOf(const std::filesystem::path& path) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) {
        return makeError(errno == ENOENT ? ErrorCode::FileNotFound : ErrorCode::FileUnreadable,
                         std::string("cannot read: ") + std::strerror(errno), {path.string()});
    }
    return snapshotFrom(path, status);
}

ForwardText::ForwardText(std::string_view whole) : m_memory(whole), m_size(whole.size()) {}

ForwardText::ForwardText(Descriptor file, std::size_t size, std::filesystem::path path)
    : m_file(std::move(file)), m_size(size), m_path(std::move(path)) {}

Result<ForwardText> ForwardText::reopen(const FileSnapshot& snapshot) {
    Descriptor file(::open(snapshot.path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!file.valid()) {
        return std::unexpected(unreadable(
            snapshot.path, std::string("cannot read the program again: ") + std::strerror(errno)));
    }
    struct stat status {};
    if (::fstat(file.get(), &status) != 0 ||
        !snapshotFrom(snapshot.path, status).sameFileAs(snapshot)) {
        return std::unexpected(unreadable(
            snapshot.path, "the program file changed while the job ran (it was written again or "
                           "replaced after it was read); nothing was written: run the job again"));
    }
    return ForwardText(std::move(file), static_cast<std::size_t>(snapshot.size), snapshot.path);
}

bool ForwardText::load(std::size_t end) {
    // What is released leaves the window; what is asked for next is read behind what is kept.
    const std::size_t keepFrom = std::max(m_windowBegin, std::min(m_released, m_size));
    m_window.erase(0, std::min(m_window.size(), keepFrom - m_windowBegin));
    m_windowBegin = keepFrom;
    std::size_t have = m_windowBegin + m_window.size();
    const std::size_t target = std::min(m_size, std::max(end, have) + kWindowBytes);
    m_window.resize(target - m_windowBegin);
    while (have < target) {
        const ssize_t got = ::pread(m_file.get(), m_window.data() + (have - m_windowBegin),
                                    target - have, static_cast<off_t>(have));
        if (got < 0 && errno == EINTR) {
            continue;
        }
        if (got <= 0) {
            m_window.resize(have - m_windowBegin);
            m_failure = unreadable(
                m_path, got < 0
                            ? std::string("cannot read the program again: ") + std::strerror(errno)
                            : "the program file was cut short while the job ran; nothing was "
                              "written: run the job again");
            return false;
        }
        have += static_cast<std::size_t>(got);
    }
    return true;
}

std::string_view ForwardText::range(std::size_t begin, std::size_t end) {
    end = std::min(end, m_size);
    begin = std::min(begin, end);
    if (!m_file.valid()) {
        return m_memory.substr(begin, end - begin);
    }
    if (begin < m_windowBegin) {
        m_failure = Error{ErrorCode::Internal,
                          "the program's text was asked for again behind "
                          "what was released",
                          {m_path.string(), 0, 0},
                          {}};
        return {};
    }
    if (end > m_windowBegin + m_window.size() && !load(end)) {
        return {};
    }
    return std::string_view(m_window).substr(begin - m_windowBegin, end - begin);
}

std::string_view ForwardText::lineFrom(std::size_t begin) {
    std::size_t probe = 256;
    while (true) {
        const std::size_t end = std::min(m_size, begin + probe);
        const std::string_view view = range(begin, end);
        if (m_failure) {
            return {};
        }
        const std::size_t newline = view.find('\n');
        if (newline != std::string_view::npos || end == m_size) {
            std::string_view line = view.substr(0, newline);
            if (!line.empty() && line.back() == '\r') {
                line.remove_suffix(1);
            }
            return line;
        }
        probe *= 2;
    }
}

} // namespace bladeaxis

#include "core/base/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

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

fs::path temporarySibling(const fs::path& path) {
    std::random_device device;
    std::string name = ".";
    name += path.filename().string();
    name += ".tmp";
    name += std::to_string(device());
    return path.parent_path() / name;
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
    const fs::path temporary = temporarySibling(path);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            return makeError(ErrorCode::WriteFailed,
                             std::string("cannot create output: ") + std::strerror(errno),
                             {path.string()});
        }
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            fs::remove(temporary, ignored);
            return makeError(ErrorCode::WriteFailed, "write failed (disk full?)", {path.string()});
        }
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return makeError(ErrorCode::WriteFailed, "cannot rename the temporary file into place",
                         {path.string()});
    }
    return {};
}

} // namespace bladeaxis

#include "core/base/file_io.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace bladeaxis {
namespace {

namespace fs = std::filesystem;

class FileIo : public ::testing::Test {
  protected:
    test::ScratchFolder m_scratch{"bladeaxis_file_io_"};
    const fs::path& m_dir = m_scratch.path();
};

TEST_F(FileIo, WrittenContentReadsBackIdentically) {
    const fs::path path = m_dir / "out.nc";
    const std::string content = "G1 X1.000\r\nM30\n";
    ASSERT_TRUE(writeFileAtomically(path, content).has_value());
    const auto back = readTextFile(path);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, content);
}

// Large enough for the back half's pages to be mapped on a second thread while the front half
// is read.
TEST_F(FileIo, ALargeFileReadsBackIdentically) {
    const fs::path path = m_dir / "large.nc";
    std::string content;
    for (int line = 0; content.size() < (24u << 20); ++line) {
        content += "N" + std::to_string(line) + " G1 X" + std::to_string(line % 977) + ".125\n";
    }
    ASSERT_TRUE(writeFileAtomically(path, content).has_value());
    const auto back = readTextFile(path);
    ASSERT_TRUE(back.has_value());
    EXPECT_TRUE(*back == content);
}

TEST_F(FileIo, MissingFileIsFileNotFoundNamingThePath) {
    const auto result = readTextFile(m_dir / "missing.nc");
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::FileNotFound);
    EXPECT_NE(result.error().toString().find("missing.nc"), std::string::npos);
}

TEST_F(FileIo, DirectoryIsNotReadableAsAFile) {
    const auto result = readTextFile(m_dir);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::FileUnreadable);
}

TEST_F(FileIo, RefusesToOverwriteAProtectedInputAndLeavesItUnchanged) {
    const fs::path input = m_dir / "in.nc";
    std::ofstream(input) << "original";
    const fs::path inputs[] = {input};
    const auto status = writeFileAtomically(m_dir / "." / "in.nc", "new", inputs);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    EXPECT_EQ(*readTextFile(input), "original");
}

TEST_F(FileIo, FailedWriteLeavesNoPartialOrTemporaryFile) {
    const auto status = writeFileAtomically(m_dir / "no_such_dir" / "out.nc", "x");
    ASSERT_FALSE(status.has_value());
    EXPECT_TRUE(fs::is_empty(m_dir));
}

// `-o /dev/stdout` in a pipe: /dev/stdout links to /proc/self/fd/1, whose link text
// ("pipe:[N]") names no file; the kernel resolves it to the pipe, which is written directly.
TEST_F(FileIo, APipeReachedThroughAProcessFdLinkIsWrittenDirectly) {
    int ends[2];
    ASSERT_EQ(::pipe(ends), 0);
    const fs::path path = "/proc/self/fd/" + std::to_string(ends[1]);
    EXPECT_FALSE(StagedFile::isStageable(path));
    const auto status = writeFileAtomically(path, "G1 X1.000\nM30\n");
    ::close(ends[1]);
    char buffer[64] = {};
    const ssize_t got = ::read(ends[0], buffer, sizeof buffer);
    ::close(ends[0]);
    ASSERT_TRUE(status.has_value()) << status.error().toString();
    EXPECT_EQ(std::string(buffer, static_cast<std::size_t>(std::max<ssize_t>(got, 0))),
              "G1 X1.000\nM30\n");
}

} // namespace
} // namespace bladeaxis

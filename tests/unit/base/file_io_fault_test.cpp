// The atomic writer under faults and unusual destinations: links, devices, pipes, a killed
// process, a full disk. A program BladeAxis writes goes to a machine that cuts an expensive part:
// the destination holds the old file or the whole new one, never a part of it.

#include "core/base/file_io.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace bladeaxis {
namespace {

namespace fs = std::filesystem;

class FileIoFaults : public ::testing::Test {
  protected:
    void put(const fs::path& path, const std::string& content) const {
        std::ofstream(path, std::ios::binary) << content;
    }
    std::string get(const fs::path& path) const { return readTextFile(path).value_or("<none>"); }
    std::size_t filesInFolder() const {
        return static_cast<std::size_t>(
            std::distance(fs::directory_iterator(m_dir), fs::directory_iterator()));
    }

    test::ScratchFolder m_scratch{"bladeaxis_file_faults_"};
    const fs::path& m_dir = m_scratch.path();
};

TEST_F(FileIoFaults, ASymbolicLinkIsFollowedAndStaysALink) {
    const fs::path target = m_dir / "program.nc";
    const fs::path link = m_dir / "latest.nc";
    put(target, "old\n");
    fs::create_symlink("program.nc", link);
    ASSERT_TRUE(writeFileAtomically(link, "new\n").has_value());
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
    EXPECT_EQ(get(target), "new\n");
}

TEST_F(FileIoFaults, ALinkToAProtectedInputIsRefusedAndTheInputKept) {
    const fs::path input = m_dir / "input.nc";
    put(input, "input\n");
    fs::create_symlink(input, m_dir / "soft.nc");
    fs::create_hard_link(input, m_dir / "hard.nc");
    const fs::path inputs[] = {input};
    for (const char* name : {"soft.nc", "hard.nc"}) {
        const auto status = writeFileAtomically(m_dir / name, "output\n", inputs);
        ASSERT_FALSE(status.has_value()) << name;
        EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
    }
    EXPECT_EQ(get(input), "input\n");
}

TEST_F(FileIoFaults, TheReplacedFileKeepsItsPermissionBits) {
    const fs::path path = m_dir / "program.nc";
    put(path, "old\n");
    ::chmod(path.c_str(), 0640);
    ASSERT_TRUE(writeFileAtomically(path, "new\n").has_value());
    struct stat info {};
    ASSERT_EQ(::stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0640u);
}

TEST_F(FileIoFaults, ACharacterDeviceIsWrittenAndStaysADevice) {
    ASSERT_TRUE(writeFileAtomically("/dev/null", "discarded\n").has_value());
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(FileIoFaults, APipeIsWrittenDirectly) {
    const fs::path fifo = m_dir / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    });
    const auto status = writeFileAtomically(fifo, "through the pipe\n");
    reader.join();
    ASSERT_TRUE(status.has_value()) << status.error().toString();
    EXPECT_EQ(received, "through the pipe\n");
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST_F(FileIoFaults, AFolderIsRefusedNamingIt) {
    const auto status = writeFileAtomically(m_dir, "x");
    ASSERT_FALSE(status.has_value());
    EXPECT_NE(status.error().message.find("folder"), std::string::npos);
}

TEST_F(FileIoFaults, AFolderThatIsAFileIsAWriteError) {
    put(m_dir / "plain", "x");
    const auto status = writeFileAtomically(m_dir / "plain" / "out.nc", "x");
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().code, ErrorCode::WriteFailed);
}

// A child process writes a large program and is killed with SIGKILL part-way: the destination
// must still hold the old file, and nothing else may be left in the folder.
TEST_F(FileIoFaults, AProcessKilledDuringTheWriteLeavesTheOldFileAndNoTemporary) {
    const fs::path path = m_dir / "program.nc";
    put(path, "old program\n");
    const std::string large(512u << 20, 'X');
    for (int delayMs : {0, 5, 40}) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            (void)writeFileAtomically(path, large);
            ::_exit(0);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        const std::string now = get(path);
        EXPECT_TRUE(now == "old program\n" || now.size() == large.size())
            << "partial file of " << now.size() << " bytes after " << delayMs << " ms";
        EXPECT_EQ(filesInFolder(), 1u) << "a temporary file was left after " << delayMs << " ms";
        put(path, "old program\n");
    }
}

// A file-size limit stands in for a full disk (no root needed): the write fails with the
// system's reason and the old file stays whole.
TEST_F(FileIoFaults, AFullDiskIsAWriteErrorAndKeepsTheOldFile) {
    const fs::path path = m_dir / "program.nc";
    put(path, "old program\n");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{1 << 16, 1 << 16};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const auto status = writeFileAtomically(path, std::string(1 << 20, 'X'));
        const bool reported = !status.has_value() &&
                              status.error().code == ErrorCode::WriteFailed &&
                              status.error().message.find("full") != std::string::npos;
        ::_exit(reported ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "the write did not fail as a full disk";
    EXPECT_EQ(get(path), "old program\n");
    EXPECT_EQ(filesInFolder(), 1u);
}

} // namespace
} // namespace bladeaxis

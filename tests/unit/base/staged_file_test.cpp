#include "core/base/file_io.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace bladeaxis {
namespace {

namespace fs = std::filesystem;

class StagedFiles : public ::testing::Test {
  protected:
    std::size_t entriesInFolder() const {
        return static_cast<std::size_t>(
            std::distance(fs::directory_iterator(m_dir), fs::directory_iterator()));
    }

    test::ScratchFolder m_scratch{"bladeaxis_staged_"};
    const fs::path& m_dir = m_scratch.path();
};

// Kilobytes of a mapping resident in this process, from /proc/self/smaps (mincore would tell
// whether the file's pages are cached, not whether this process maps them).
std::size_t residentKilobytesOfMappingAt(const void* start) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inMapping = false;
    while (std::getline(smaps, line)) {
        const std::size_t dash = line.find('-');
        if (dash != std::string::npos && dash < 17 && line.find(' ') > dash) {
            const auto begin = std::stoull(line.substr(0, dash), nullptr, 16);
            inMapping = begin == reinterpret_cast<std::uintptr_t>(start);
            continue;
        }
        if (inMapping && line.rfind("Rss:", 0) == 0) {
            std::istringstream fields(line.substr(4));
            std::size_t kilobytes = 0;
            fields >> kilobytes;
            return kilobytes;
        }
    }
    ADD_FAILURE() << "no mapping starts at " << start;
    return 0;
}

TEST_F(StagedFiles, PiecesAppendedAndCommittedReadBackAsOneFile) {
    const fs::path path = m_dir / "out.nc";
    auto staged = StagedFile::open(path);
    ASSERT_TRUE(staged.has_value()) << staged.error().toString();
    ASSERT_TRUE(staged->append("G1 X1.000\n").has_value());
    ASSERT_TRUE(staged->append("M30\n").has_value());
    EXPECT_EQ(staged->size(), 14U);
    EXPECT_FALSE(fs::exists(path)); // nothing is in place before the commit
    ASSERT_TRUE(staged->commit().has_value());
    EXPECT_EQ(*readTextFile(path), "G1 X1.000\nM30\n");
    // A second commit finds it in place and leaves the folder as it is.
    ASSERT_TRUE(staged->commit().has_value());
    EXPECT_EQ(entriesInFolder(), 1U);
}

TEST_F(StagedFiles, AFileDroppedUncommittedLeavesTheFolderAndTheOldFileAsTheyWere) {
    const fs::path path = m_dir / "out.nc";
    std::ofstream(path) << "old program";
    {
        auto staged = StagedFile::open(path);
        ASSERT_TRUE(staged.has_value());
        ASSERT_TRUE(staged->append("half a new progr").has_value());
    }
    EXPECT_EQ(*readTextFile(path), "old program");
    EXPECT_EQ(entriesInFolder(), 1U);
}

TEST_F(StagedFiles, ACommitKeepsThePermissionBitsOfTheFileItReplaces) {
    const fs::path path = m_dir / "out.nc";
    std::ofstream(path) << "old";
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    auto staged = StagedFile::open(path);
    ASSERT_TRUE(staged.has_value());
    ASSERT_TRUE(staged->append("new").has_value());
    ASSERT_TRUE(staged->commit().has_value());
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(StagedFiles, AnInputIsNeverATargetAndAFolderOrAPipeCannotBeStaged) {
    const fs::path input = m_dir / "in.nc";
    std::ofstream(input) << "original";
    const fs::path inputs[] = {input};
    const auto refused = StagedFile::open(m_dir / "." / "in.nc", inputs);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::WriteFailed);
    EXPECT_EQ(*readTextFile(input), "original");

    const fs::path pipe = m_dir / "pipe";
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    EXPECT_FALSE(StagedFile::isStageable(pipe));
    EXPECT_FALSE(StagedFile::isStageable(m_dir));
    EXPECT_FALSE(StagedFile::isStageable(m_dir / "no_such_folder" / "out.nc"));
    EXPECT_TRUE(StagedFile::isStageable(m_dir / "new.nc"));
    EXPECT_TRUE(StagedFile::isStageable(input));
    const auto folder = StagedFile::open(m_dir);
    ASSERT_FALSE(folder.has_value());
    EXPECT_NE(folder.error().toString().find("neither a regular file"), std::string::npos);
}

TEST_F(StagedFiles, MappedTextGivesPagesBackAndStillReadsTheSameBytes) {
    auto staged = StagedFile::open(m_dir / "out.nc");
    ASSERT_TRUE(staged.has_value());
    std::string content;
    for (int i = 0; content.size() < (std::size_t{2} << 20); ++i) {
        content += "G1 X" + std::to_string(i) + ".000 Y-3.250 Z1.500 A" + std::to_string(i % 360) +
                   ".0000\n";
    }
    ASSERT_TRUE(staged->append(content).has_value());
    auto mapped = staged->mapText();
    ASSERT_TRUE(mapped.has_value()) << mapped.error().toString();
    ASSERT_EQ(mapped->text(), content); // reads every page in
    const std::size_t before = residentKilobytesOfMappingAt(mapped->text().data());
    EXPECT_GE(before, 2000U);
    mapped->releaseBefore(content.size() - 100'000);
    const std::size_t after = residentKilobytesOfMappingAt(mapped->text().data());
    EXPECT_LE(after, 104U) << "before " << before << " kB";
    EXPECT_EQ(mapped->text(), content); // the pages come back from the file
}

// The longest names a file system takes (241 to 255 bytes) were refused with "File name too
// long": the temporary beside them was named after them and longer still.
TEST_F(StagedFiles, AnOutputWithTheLongestLegalNameIsWrittenThroughAShortTemporary) {
    for (const std::size_t length : {241U, 250U, 255U}) {
        const fs::path target = m_dir / std::string(length, 'n');
        ASSERT_TRUE(writeFileAtomically(target, "old\n"));
        const Status replaced = writeFileAtomically(target, "new\n");
        ASSERT_TRUE(replaced) << replaced.error().toString();
        EXPECT_EQ(readTextFile(target).value_or(""), "new\n");
    }
    EXPECT_EQ(entriesInFolder(), 3U) << "no temporary left behind";
}

// Where a file system cannot make unnamed files, a killed run leaves its temporary: a short
// hidden name that says whose it is, whatever the target's name.
TEST_F(StagedFiles, ATemporaryNameIsShortAndHiddenWhateverTheTarget) {
    const fs::path name = temporaryNameIn(m_dir);
    EXPECT_EQ(name.parent_path(), m_dir);
    EXPECT_TRUE(name.filename().string().starts_with(".ba-"));
    EXPECT_EQ(name.filename().string().size(), 10U);
    EXPECT_NE(temporaryNameIn(m_dir), name) << "random";
}

} // namespace
} // namespace bladeaxis

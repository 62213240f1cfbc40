#include "core/base/output_set.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace bladeaxis {
namespace {

namespace fs = std::filesystem;

class OutputSets : public ::testing::Test {
  protected:
    void write(const fs::path& path, const std::string& text) const {
        std::ofstream(path, std::ios::binary) << text;
    }
    std::size_t entriesIn(const fs::path& folder) const {
        return static_cast<std::size_t>(
            std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
    }

    test::ScratchFolder m_scratch{"bladeaxis_output_set_"};
    const fs::path& m_dir = m_scratch.path();
};

TEST_F(OutputSets, NothingIsPublishedBeforeEveryOutputIsStaged) {
    write(m_dir / "program.nc", "old program\n");
    fs::create_directory(m_dir / "report.json"); // a folder where the report goes
    OutputSet outputs;
    ASSERT_TRUE(outputs.add(m_dir / "program.nc", "new program\n"));
    const Status report = outputs.add(m_dir / "report.json", "{}\n");
    ASSERT_FALSE(report);
    EXPECT_EQ(report.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(report.error().message.find("is a folder"), std::string::npos);
    EXPECT_FALSE(outputs.add(m_dir / "missing" / "x.cl", "GOTO\n")) << "a folder that is not there";
    EXPECT_EQ(readTextFile(m_dir / "program.nc").value_or(""), "old program\n");
    EXPECT_EQ(entriesIn(m_dir), 2U) << "no temporary left behind";
}

// A move that fails after others were made (here the second file's folder went away between
// staging and publishing) puts the first file's old content back and removes a new one.
TEST_F(OutputSets, AFailedPublishUndoesTheFilesAlreadyMovedIntoPlace) {
    write(m_dir / "program.nc", "old program\n");
    fs::create_directory(m_dir / "report");
    OutputSet outputs;
    ASSERT_TRUE(outputs.add(m_dir / "program.nc", "new program\n"));
    ASSERT_TRUE(outputs.add(m_dir / "new.cl", "GOTO\n"));
    ASSERT_TRUE(outputs.add(m_dir / "report" / "report.json", "{}\n"));
    fs::rename(m_dir / "report", m_dir / "moved");
    const Status published = outputs.publish();
    ASSERT_FALSE(published);
    EXPECT_EQ(published.error().code, ErrorCode::WriteFailed);
    EXPECT_EQ(readTextFile(m_dir / "program.nc").value_or(""), "old program\n");
    EXPECT_FALSE(fs::exists(m_dir / "new.cl"));
    EXPECT_EQ(entriesIn(m_dir), 2U) << "program.nc and moved/, no second name left";
}

TEST_F(OutputSets, APublishedSetReplacesEveryFileAndLeavesNoSecondName) {
    write(m_dir / "program.nc", "old program\n");
    OutputSet outputs;
    ASSERT_TRUE(outputs.add(m_dir / "program.nc", "new program\n"));
    ASSERT_TRUE(outputs.add(m_dir / "report.json", "{}\n"));
    ASSERT_TRUE(outputs.add("/dev/null", "to a device, written last\n"));
    ASSERT_TRUE(outputs.publish());
    EXPECT_EQ(readTextFile(m_dir / "program.nc").value_or(""), "new program\n");
    EXPECT_EQ(readTextFile(m_dir / "report.json").value_or(""), "{}\n");
    EXPECT_EQ(entriesIn(m_dir), 2U);
}

TEST_F(OutputSets, AnOutputFolderThisRunMadeIsRemovedUnlessKept) {
    {
        auto created = CreatedFolder::create(m_dir / "a" / "b");
        ASSERT_TRUE(created);
        EXPECT_TRUE(fs::is_directory(m_dir / "a" / "b"));
    }
    EXPECT_FALSE(fs::exists(m_dir / "a")) << "both folders it made";
    {
        auto created = CreatedFolder::create(m_dir / "kept");
        ASSERT_TRUE(created);
        created->keep();
    }
    EXPECT_TRUE(fs::is_directory(m_dir / "kept"));
    {
        auto existing = CreatedFolder::create(m_dir / "kept");
        ASSERT_TRUE(existing);
    }
    EXPECT_TRUE(fs::is_directory(m_dir / "kept")) << "not made by this run";
    write(m_dir / "file", "x");
    EXPECT_FALSE(CreatedFolder::create(m_dir / "file"));
}

} // namespace
} // namespace bladeaxis

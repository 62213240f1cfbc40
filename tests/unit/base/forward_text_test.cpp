#include "core/base/forward_text.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace bladeaxis {
namespace {

namespace fs = std::filesystem;

class ForwardTexts : public ::testing::Test {
  protected:
    void SetUp() override {
        // Lines ending in CR LF, one of them far longer than a first look at a line, spread
        // over several of the file's windows.
        for (int i = 0; m_text.size() < (std::size_t{9} << 20); ++i) {
            m_text += "N" + std::to_string(i) + " G1 X" + std::to_string(i % 977) + ".125 A" +
                      std::to_string(i % 360) + ".0\r\n";
            if (i == 1000) {
                m_text += "(" + std::string(5000, 'c') + ")\r\n";
            }
        }
        std::ofstream(m_file, std::ios::binary) << m_text;
    }
    ForwardText reopened() const {
        auto snapshot = snapshotOf(m_file);
        EXPECT_TRUE(snapshot.has_value());
        auto text = ForwardText::reopen(*snapshot);
        EXPECT_TRUE(text.has_value()) << text.error().toString();
        return std::move(*text);
    }

    test::ScratchFolder m_scratch{"bladeaxis_forward_"};
    const fs::path m_file = m_scratch.path() / "program.nc";
    std::string m_text;
};

// Every line, read front to back with what is behind released, as the rewrite reads it.
std::string linesOf(ForwardText& text) {
    std::string lines;
    std::size_t begin = 0;
    while (begin < text.size()) {
        const std::string_view line = text.lineFrom(begin);
        EXPECT_FALSE(text.failure().has_value());
        lines.append(line).append("|");
        text.releaseBefore(begin);
        begin += line.size() + 2; // every line ends in CR LF
    }
    return lines;
}

TEST_F(ForwardTexts, AFileReadAgainGivesTheLinesAndRangesOfTheTextInMemory) {
    ForwardText inMemory(m_text);
    ForwardText fromFile = reopened();
    EXPECT_EQ(fromFile.size(), m_text.size());
    EXPECT_EQ(linesOf(fromFile), linesOf(inMemory));

    ForwardText again = reopened();
    const std::size_t step = (std::size_t{3} << 20) + 17; // across the windows' ends
    for (std::size_t begin = 0; begin < m_text.size(); begin += step) {
        EXPECT_EQ(again.range(begin, begin + step), std::string_view(m_text).substr(begin, step));
        again.releaseBefore(begin);
    }
    EXPECT_FALSE(again.failure().has_value());
}

TEST_F(ForwardTexts, AskingAgainBehindWhatWasReleasedIsAnInternalFailure) {
    ForwardText text = reopened();
    text.releaseBefore(6u << 20);
    (void)text.range(7u << 20, 8u << 20);
    EXPECT_TRUE(text.range(10, 20).empty());
    ASSERT_TRUE(text.failure().has_value());
    EXPECT_EQ(text.failure()->code, ErrorCode::Internal);
}

TEST_F(ForwardTexts, AFileWrittenAgainOrCutShortIsRefused) {
    const auto snapshot = snapshotOf(m_file);
    ASSERT_TRUE(snapshot.has_value());
    ForwardText opened = reopened();
    fs::resize_file(m_file, m_text.size() / 2); // cut short after it was opened
    (void)opened.range(0, 100);
    EXPECT_TRUE(opened.range(m_text.size() - 100, m_text.size()).empty());
    ASSERT_TRUE(opened.failure().has_value());
    EXPECT_NE(opened.failure()->toString().find("cut short"), std::string::npos);

    const auto refused = ForwardText::reopen(*snapshot); // no longer the file that was read
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::FileUnreadable);
    EXPECT_NE(refused.error().toString().find("changed while the job ran"), std::string::npos);
}

} // namespace
} // namespace bladeaxis

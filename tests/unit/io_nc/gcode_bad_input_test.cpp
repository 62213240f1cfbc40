// The bad-input corpus: every tests/data/bad/nc/<name>.nc has a sibling <name>.expected holding
// a substring of the expected error ("name.nc:3:7: parse error: ..."). New cases are added by
// dropping two files into the folder.

#include "core/io/nc/gcode_reader.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace bladeaxis::io::nc {
namespace {

namespace fs = std::filesystem;

fs::path badDir() {
    return fs::path(BLADEAXIS_TEST_DATA_DIR) / "bad" / "nc";
}

// File names: ISO programs (.nc), Sinumerik (.mpf) and Heidenhain (.h), each dialect found
// from its extension and content as a user's file would be.
std::vector<std::string> badCases() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(badDir())) {
        const std::string extension = entry.path().extension().string();
        if (extension == ".nc" || extension == ".mpf" || extension == ".h") {
            names.push_back(entry.path().filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) {
        text.pop_back();
    }
    return text;
}

class BadGcode : public ::testing::TestWithParam<std::string> {};

TEST_P(BadGcode, IsRejectedWithTheExpectedLocatedMessage) {
    const fs::path input = badDir() / GetParam();
    const Result<std::string> expected =
        readTextFile(badDir() / (input.stem().string() + ".expected"));
    ASSERT_TRUE(expected.has_value()) << "missing " << GetParam() << ".expected";
    const std::string wanted = trimmed(*expected);
    ASSERT_FALSE(wanted.empty());

    const Result<GcodeProgram> program = readGcodeFile(input, kinematics::defaultBladeMachine());
    ASSERT_FALSE(program.has_value()) << GetParam() << " was accepted";
    EXPECT_EQ(program.error().code, ErrorCode::Parse);
    EXPECT_NE(program.error().toString().find(wanted), std::string::npos)
        << "expected '" << wanted << "' in:\n"
        << program.error().toString();
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadGcode, ::testing::ValuesIn(badCases()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string name = param.param;
                             std::replace_if(
                                 name.begin(), name.end(),
                                 [](char c) {
                                     return !std::isalnum(static_cast<unsigned char>(c));
                                 },
                                 '_');
                             return name;
                         });

TEST(BadGcodeCorpus, HasAtLeastFifteenCases) {
    EXPECT_GE(badCases().size(), 15u);
}

} // namespace
} // namespace bladeaxis::io::nc

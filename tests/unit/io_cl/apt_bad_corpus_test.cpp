// Every file in tests/data/bad/cl/ must be rejected with the message stored beside it in
// <name>.expected ("file:line:column: parse error: ..."). Adding a case needs no code.

#include "core/io/cl/apt.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bladeaxis::io::cl {
namespace {

namespace fs = std::filesystem;

const fs::path kBadDir = fs::path(BLADEAXIS_TEST_DATA_DIR) / "bad" / "cl";

std::vector<std::string> badCases() {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kBadDir)) {
        if (entry.is_regular_file() && entry.path().extension() != ".expected") {
            names.push_back(entry.path().filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string readExpected(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) {
        text.pop_back();
    }
    return text;
}

class BadClFile : public ::testing::TestWithParam<std::string> {};

TEST_P(BadClFile, IsRejectedWithItsExpectedLocationAndMessage) {
    const fs::path input = kBadDir / GetParam();
    const fs::path expectedFile = kBadDir / (GetParam() + ".expected");
    ASSERT_TRUE(fs::exists(expectedFile)) << "missing " << expectedFile;
    const std::string expected = readExpected(expectedFile);
    ASSERT_FALSE(expected.empty());

    Result<AptProgram> program = readAptFile(input);
    ASSERT_FALSE(program.has_value()) << GetParam() << " was accepted";
    EXPECT_EQ(program.error().code, ErrorCode::Parse);
    EXPECT_NE(program.error().toString().find(expected), std::string::npos)
        << "expected: " << expected << "\nactual:   " << program.error().toString();
}

TEST(BadClCorpus, HoldsAtLeastTenCases) {
    EXPECT_GE(badCases().size(), 10u);
}

std::string caseName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    std::replace_if(
        name.begin(), name.end(),
        [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadClFile, ::testing::ValuesIn(badCases()), caseName);

} // namespace
} // namespace bladeaxis::io::cl

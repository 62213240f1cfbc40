#include "core/io/cl/apt.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace bladeaxis::io::cl {
namespace {

namespace fs = std::filesystem;

const fs::path kClDir = fs::path(BLADEAXIS_TEST_DATA_DIR) / "cl";

AptProgram readSample(const std::string& name) {
    Result<AptProgram> program = readAptFile(kClDir / name);
    EXPECT_TRUE(program.has_value()) << program.error().toString();
    return program ? std::move(*program) : AptProgram{};
}

// Lines of `text` that differ from `original` (same number of lines expected).
std::vector<std::size_t> changedLines(const std::string& original, const std::string& text) {
    auto split = [](const std::string& s) {
        std::vector<std::string> lines;
        std::size_t begin = 0;
        while (begin <= s.size()) {
            std::size_t end = s.find('\n', begin);
            lines.push_back(s.substr(begin, end == std::string::npos ? end : end - begin));
            if (end == std::string::npos) {
                break;
            }
            begin = end + 1;
        }
        return lines;
    };
    const auto a = split(original);
    const auto b = split(text);
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
        if (i >= a.size() || i >= b.size() || a[i] != b[i]) {
            changed.push_back(i + 1);
        }
    }
    return changed;
}

class RewriteSample : public ::testing::TestWithParam<std::string> {};

TEST_P(RewriteSample, WithTheOriginalRecordsIsByteIdentical) {
    const AptProgram program = readSample(GetParam());
    Result<std::string> text = rewriteApt(program, program.path.records);
    ASSERT_TRUE(text.has_value()) << text.error().toString();
    EXPECT_EQ(*text, program.text);
}

TEST_P(RewriteSample, ChangedRecordsReadBackWithTheirNewValues) {
    const AptProgram program = readSample(GetParam());
    std::vector<toolpath::ClRecord> records = program.path.records;
    for (std::size_t i = 0; i < records.size(); i += 3) {
        records[i].tip += Vec3(0.5, -0.25, 1.0);
        records[i].axis = (records[i].axis + Vec3(0.1, 0.2, 0.0)).normalized();
    }
    Result<std::string> text = rewriteApt(program, records);
    ASSERT_TRUE(text.has_value()) << text.error().toString();
    Result<AptProgram> reread = parseApt(*text, "rewritten");
    ASSERT_TRUE(reread.has_value()) << reread.error().toString();
    ASSERT_EQ(reread->path.records.size(), records.size());
    // The samples carry 4 decimals (inches.apt: 4 decimals of an inch).
    for (std::size_t i = 0; i < records.size(); ++i) {
        EXPECT_LT((reread->path.records[i].tip - records[i].tip).norm(), 3e-3) << i;
        EXPECT_LT((reread->path.records[i].axis - records[i].axis).norm(), 2e-6) << i;
        EXPECT_EQ(reread->path.records[i].motion, program.path.records[i].motion) << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Samples, RewriteSample,
                         ::testing::Values("nx_clsf_crlf.cls", "classic_apt.apt", "inches.apt"),
                         [](const auto& param) {
                             return param.param.substr(0, param.param.find('.'));
                         });

// A six-number GOTO followed by another six-number GOTO: no later statement inherits its axis.
std::size_t isolatedSixNumberGoto(const AptProgram& program) {
    const auto& source = program.source;
    for (std::size_t i = source.size() / 2; i + 1 < source.size(); ++i) {
        if (source[i].numberCount == 6 && source[i + 1].numberCount == 6) {
            return i;
        }
    }
    return source.size();
}

class RewriteSixNumberSample : public ::testing::TestWithParam<std::string> {};

TEST_P(RewriteSixNumberSample, ChangingOneAxisChangesOnlyItsStatement) {
    const AptProgram program = readSample(GetParam());
    const std::size_t index = isolatedSixNumberGoto(program);
    ASSERT_LT(index, program.source.size());
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[index].axis = Vec3(0.3, -0.2, 0.9).normalized();
    Result<std::string> text = rewriteApt(program, records);
    ASSERT_TRUE(text.has_value()) << text.error().toString();
    const std::vector<std::size_t> changed = changedLines(program.text, *text);
    ASSERT_FALSE(changed.empty());
    for (std::size_t line : changed) {
        // A continued statement may change on any of its lines.
        EXPECT_GE(line, static_cast<std::size_t>(records[index].line));
        EXPECT_LT(line, static_cast<std::size_t>(program.path.records[index + 1].line));
    }
    Result<AptProgram> reread = parseApt(*text, "rewritten");
    ASSERT_TRUE(reread.has_value()) << reread.error().toString();
    EXPECT_LT((reread->path.records[index].axis - records[index].axis).norm(), 1e-6);
    EXPECT_EQ(reread->path.records[index + 1].axis, program.path.records[index + 1].axis);
}

INSTANTIATE_TEST_SUITE_P(Samples, RewriteSixNumberSample,
                         ::testing::Values("nx_clsf_crlf.cls", "classic_apt.apt"),
                         [](const auto& param) {
                             return param.param.substr(0, param.param.find('.'));
                         });

TEST(RewriteApt, KeepsDecimalsAndLayoutOfChangedNumbers) {
    const AptProgram program = *parseApt("FEDRAT/60\ngoto / 1.50 , 2.0,3 ,0,0,1\n", "t.cls");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].tip = Vec3(1.5, 7.25, 3.5);
    EXPECT_EQ(rewriteApt(program, records).value(), "FEDRAT/60\ngoto / 1.50 , 7.2,3.5 ,0,0,1\n");
}

TEST(RewriteApt, RewritesNumbersInsideDollarContinuations) {
    const std::string text = "FEDRAT/60\r\nGOTO/1.000,2.000,$\r\n 3.000,$\r\n0.0,0.0,1.0";
    const AptProgram program = *parseApt(text, "t.cls");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].tip.z() = 4.0;
    records[0].axis = Vec3(1, 0, 0);
    EXPECT_EQ(rewriteApt(program, records).value(),
              "FEDRAT/60\r\nGOTO/1.000,2.000,$\r\n 4.000,$\r\n1.0,0.0,0.0");
}

// CATIA V5 breaks APT lines at column 72, inside numbers too.
TEST(RewriteApt, KeepsTheSplitOfANumberBrokenByAContinuation) {
    const std::string text =
        "FEDRAT/60\nGOTO/1.000,2.000,3.12$\n345,0.000000,0.000000,1.00000$\n0\n";
    const AptProgram program = *parseApt(text, "t.apt");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].tip.z() = 4.56789;
    records[0].axis = Vec3(0, 0.6, 0.8);
    EXPECT_EQ(rewriteApt(program, records).value(),
              "FEDRAT/60\nGOTO/1.000,2.000,4.56$\n789,0.000000,0.600000,0.80000$\n0\n");
}

// A last piece of one character must not become an empty line: the continuation would then
// join the next statement to this one.
TEST(RewriteApt, NeverEmptiesTheLastLineOfASplitNumber) {
    const std::string text =
        "FEDRAT/60\nGOTO/1.0,2.0,3.0,0.000000,0.000000,1.00000$\n0\nGOTO/1.0,2.0,3.5\n";
    const AptProgram program = *parseApt(text, "t.apt");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].axis = Vec3(0, 0.6, 0.8);
    records[1].axis = records[0].axis;
    Result<std::string> rewritten = rewriteApt(program, records);
    ASSERT_TRUE(rewritten.has_value()) << rewritten.error().toString();
    EXPECT_EQ(*rewritten,
              "FEDRAT/60\nGOTO/1.0,2.0,3.0,0.000000,0.600000,0.80000$\n0\nGOTO/1.0,2.0,3.5\n");
    Result<AptProgram> reread = parseApt(*rewritten, "rewritten");
    ASSERT_TRUE(reread.has_value()) << reread.error().toString();
    ASSERT_EQ(reread->path.records.size(), 2u);
    EXPECT_LT((reread->path.records[0].axis - records[0].axis).norm(), 1e-9);
}

// A longer or shorter new number: the pieces before the last keep their widths as far as the
// text allows and the last piece takes the rest (never nothing).
TEST(RewriteApt, ASplitNumberThatChangesLengthStillReadsBack) {
    const std::string text = "FEDRAT/60\nGOTO/1.0,2.0,-9.9$\n9,0,0,1\nGOTO/1.0,2.0,3.5,0,0,1\n";
    const AptProgram program = *parseApt(text, "t.apt");
    for (double z : {-10.25, 0.5, 5.0}) {
        std::vector<toolpath::ClRecord> records = program.path.records;
        records[0].tip.z() = z;
        Result<std::string> rewritten = rewriteApt(program, records);
        ASSERT_TRUE(rewritten.has_value()) << rewritten.error().toString();
        Result<AptProgram> reread = parseApt(*rewritten, "rewritten");
        ASSERT_TRUE(reread.has_value()) << *rewritten << reread.error().toString();
        ASSERT_EQ(reread->path.records.size(), 2u) << *rewritten;
        EXPECT_DOUBLE_EQ(reread->path.records[0].tip.z(), z) << *rewritten;
    }
}

TEST(RewriteApt, AppendsTheAxisAndInsertsMultaxWhenAThreeNumberGotoTurns) {
    const AptProgram program = *parseApt("FEDRAT/60\r\nGOTO/1.000,2.000,3.000\r\nGOTO/1.000,2.000,"
                                         "4.000\r\nGOTO/1.000,2.000,5.000\r\n",
                                         "t.cls");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[1].axis = Vec3(0, 1, 0);
    records[2].axis = Vec3(0, 1, 0);
    EXPECT_EQ(rewriteApt(program, records).value(),
              "FEDRAT/60\r\nGOTO/1.000,2.000,3.000\r\nMULTAX/ON\r\nGOTO/1.000,2.000,4.000,"
              "0.000000,1.000000,0.000000\r\nGOTO/1.000,2.000,5.000\r\n");
}

TEST(RewriteApt, AppendsTheOldAxisWhenAThreeNumberGotoFollowsAChangedOne) {
    const AptProgram program = *parseApt("MULTAX\nFEDRAT/60\nGOTO/1,2,3,0,0,1\nGOTO/1,2,4", "t");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].axis = Vec3(1, 0, 0);
    EXPECT_EQ(rewriteApt(program, records).value(),
              "MULTAX\nFEDRAT/60\nGOTO/1,2,3,1,0,0\nGOTO/1,2,4,0.000000,0.000000,1.000000");
}

TEST(RewriteApt, ConvertsNewTipsBackToInches) {
    const AptProgram program =
        *parseApt("UNITS/INCHES\nFEDRAT/10\nGOTO/1.0000,2.0000,3.0000\n", "t");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records[0].tip.x() = 50.8;
    EXPECT_EQ(rewriteApt(program, records).value(),
              "UNITS/INCHES\nFEDRAT/10\nGOTO/2.0000,2.0000,3.0000\n");
}

TEST(RewriteApt, RejectsASizeMismatchAndNonFiniteValues) {
    const AptProgram program = *parseApt("FEDRAT/60\nGOTO/1,2,3\n", "t");
    std::vector<toolpath::ClRecord> records = program.path.records;
    records.push_back(records[0]);
    EXPECT_FALSE(rewriteApt(program, records).has_value());
    records.pop_back();
    records[0].tip.y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(rewriteApt(program, records).has_value());
    records[0] = program.path.records[0];
    records[0].axis = Vec3::Zero();
    EXPECT_FALSE(rewriteApt(program, records).has_value());
}

TEST(WriteAptFile, WritesTheRewriteAndRefusesToOverwriteTheInput) {
    const fs::path dir = fs::temp_directory_path() / "bladeaxis_io_cl_write_test";
    fs::create_directories(dir);
    const fs::path input = dir / "in.cls";
    fs::copy_file(kClDir / "classic_apt.apt", input, fs::copy_options::overwrite_existing);
    Result<AptProgram> program = readAptFile(input);
    ASSERT_TRUE(program.has_value());
    EXPECT_FALSE(writeAptFile(input, *program, program->path.records).has_value());
    const fs::path output = dir / "out.cls";
    ASSERT_TRUE(writeAptFile(output, *program, program->path.records).has_value());
    Result<AptProgram> written = readAptFile(output);
    ASSERT_TRUE(written.has_value());
    EXPECT_EQ(written->text, program->text);
    fs::remove_all(dir);
}

} // namespace
} // namespace bladeaxis::io::cl

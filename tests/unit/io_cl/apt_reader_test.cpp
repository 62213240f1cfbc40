#include "core/io/cl/apt.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace bladeaxis::io::cl {
namespace {

namespace fs = std::filesystem;
using toolpath::MotionKind;

const fs::path kClDir = fs::path(BLADEAXIS_TEST_DATA_DIR) / "cl";

AptProgram parseOk(std::string_view text) {
    Result<AptProgram> program = parseApt(text, "test.cls");
    EXPECT_TRUE(program.has_value()) << program.error().toString();
    return program ? std::move(*program) : AptProgram{};
}

TEST(ParseApt, ReadsTipAxisFeedMotionAndLine) {
    const AptProgram program = parseOk("MULTAX\nFEDRAT/MMPM,600\n\nGOTO/1,2,3,0,0,2\n");
    ASSERT_EQ(program.path.records.size(), 1u);
    const toolpath::ClRecord& record = program.path.records[0];
    EXPECT_EQ(record.tip, Vec3(1, 2, 3));
    EXPECT_EQ(record.axis, Vec3(0, 0, 1)); // normalised
    EXPECT_DOUBLE_EQ(record.feed, 10.0);   // 600 mm/min
    EXPECT_EQ(record.motion, MotionKind::Feed);
    EXPECT_EQ(record.line, 4);
    EXPECT_FALSE(record.axes.has_value());
    EXPECT_EQ(program.path.format, toolpath::SourceFormat::Apt);
    EXPECT_EQ(program.path.sourceFile, "test.cls");
}

TEST(ParseApt, ThreeNumberGotoKeepsTheLastAxisStartingAtPlusZ) {
    const AptProgram program = parseOk("FEDRAT/60\nGOTO/0,0,0\nGOTO/1,0,0,1,0,0\nGOTO/2,0,0\n");
    ASSERT_EQ(program.path.records.size(), 3u);
    EXPECT_EQ(program.path.records[0].axis, Vec3::UnitZ());
    EXPECT_EQ(program.path.records[2].axis, Vec3::UnitX());
}

TEST(ParseApt, RapidAppliesToTheNextMotionOnly) {
    const AptProgram program = parseOk("FEDRAT/120\nRAPID\nGOTO/0,0,9\nGOTO/0,0,1\n");
    ASSERT_EQ(program.path.records.size(), 2u);
    EXPECT_EQ(program.path.records[0].motion, MotionKind::Rapid);
    EXPECT_EQ(program.path.records[0].feed, 0.0);
    EXPECT_EQ(program.path.records[1].motion, MotionKind::Feed);
    EXPECT_DOUBLE_EQ(program.path.records[1].feed, 2.0);
}

TEST(ParseApt, RapidWithoutAnyFedratIsAccepted) {
    EXPECT_TRUE(parseApt("RAPID\nGOTO/0,0,9\n", "r.cls").has_value());
}

TEST(ParseApt, AcceptsEveryFeedSpelling) {
    const AptProgram program = parseOk("FEDRAT/300\nGOTO/0,0,0\nFEDRAT/600,MMPM\nGOTO/0,0,1\n"
                                       "FEDRAT/IPM,10\nGOTO/0,0,2\nFEDRAT/10,ipm\nGOTO/0,0,3\n");
    ASSERT_EQ(program.path.records.size(), 4u);
    EXPECT_DOUBLE_EQ(program.path.records[0].feed, 5.0);
    EXPECT_DOUBLE_EQ(program.path.records[1].feed, 10.0);
    EXPECT_DOUBLE_EQ(program.path.records[2].feed, 254.0 / 60.0);
    EXPECT_DOUBLE_EQ(program.path.records[3].feed, 254.0 / 60.0);
}

TEST(ParseApt, AcceptsLowercaseAndSpacesAroundSlashAndCommas) {
    const AptProgram program = parseOk("fedrat / 60\n  goto / 1 , 2 ,3 , 0, 1 ,0  \n");
    ASSERT_EQ(program.path.records.size(), 1u);
    EXPECT_EQ(program.path.records[0].tip, Vec3(1, 2, 3));
    EXPECT_EQ(program.path.records[0].axis, Vec3::UnitY());
}

TEST(ParseApt, JoinsDollarContinuationsAndKeepsTheFirstLine) {
    const AptProgram program =
        parseOk("FEDRAT/60\n$$ comment\nGOTO/1,2,$ $$ note\n$$ inner comment\n3,$\n0,0,1\n");
    ASSERT_EQ(program.path.records.size(), 1u);
    EXPECT_EQ(program.path.records[0].tip, Vec3(1, 2, 3));
    EXPECT_EQ(program.path.records[0].line, 3);
}

TEST(ParseApt, ConvertsInchesToMillimetres) {
    const AptProgram program =
        parseOk("UNITS/INCHES\nCUTTER/0.5\nFEDRAT/10\nGOTO/1,2,3\nUNITS/MM\nGOTO/1,2,3\n");
    ASSERT_EQ(program.path.records.size(), 2u);
    EXPECT_LT((program.path.records[0].tip - Vec3(25.4, 50.8, 76.2)).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(program.path.records[0].feed, 254.0 / 60.0);
    EXPECT_EQ(program.path.records[1].tip, Vec3(1, 2, 3));
    ASSERT_TRUE(program.path.toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*program.path.toolRadius, 6.35);
}

TEST(ParseApt, TakesTheBallRadiusFromTldataAndCutter) {
    const AptProgram nx =
        parseOk("TLDATA/MILL,10.0000,5.0000,75.0000,0,0\nRAPID\nGOTO/0,0,0\nFINI\n");
    EXPECT_EQ(nx.path.toolRadius, 5.0);
    EXPECT_TRUE(nx.path.warnings.empty());
    const AptProgram apt = parseOk("CUTTER/12\nRAPID\nGOTO/0,0,0\n");
    EXPECT_EQ(apt.path.toolRadius, 6.0);
}

// The reader records such a cutter with its line; the job decides (it refuses to re-schedule
// it unless the job states a ball).
TEST(ParseApt, RecordsAFlatOrBullNoseCutterWithItsLineAndGivesNoRadius) {
    for (const char* cutter : {"CUTTER/8,0", "CUTTER/8,1", "TLDATA/MILL,8,1"}) {
        const std::string text = std::string("PARTNO X\n") + cutter + "\nRAPID\nGOTO/0,0,0\nFINI\n";
        const AptProgram program = parseOk(text);
        EXPECT_FALSE(program.path.toolRadius.has_value()) << cutter;
        ASSERT_TRUE(program.path.nonBallCutter.has_value()) << cutter;
        EXPECT_EQ(program.path.nonBallCutter->line, 2) << cutter;
        EXPECT_EQ(program.path.nonBallCutter->statement, cutter);
        EXPECT_EQ(program.path.nonBallCutter->diameter, 8.0) << cutter;
    }
    const AptProgram ball = parseOk("CUTTER/8,4\nRAPID\nGOTO/0,0,0\n");
    EXPECT_EQ(ball.path.toolRadius, 4.0);
    EXPECT_FALSE(ball.path.nonBallCutter.has_value());
}

TEST(ParseApt, IgnoresOtherMajorWordsAndStopsAtFini) {
    const AptProgram program = parseOk("PARTNO P\nTOOL PATH/OP1,TOOL,T1\nPAINT/COLOR,3\n"
                                       "LOADTL/1\nSPINDL/3000\nCOOLNT/ON\nMSYS/0,0,0,1,0,0,0,1,0\n"
                                       "CUTCOM/OFF\nPPRINT HELLO, GOTO/9\nEND-OF-PATH\n"
                                       "RAPID\nGOTO/0,0,0\nEND\nFINI\nGOTO/1,2\nnot apt at all\n");
    EXPECT_EQ(program.path.records.size(), 1u);
}

TEST(ParseApt, SkipsAUtf8ByteOrderMark) {
    const AptProgram program = parseOk("\xEF\xBB\xBFRAPID\nGOTO/0,0,9\n");
    ASSERT_EQ(program.path.records.size(), 1u);
    EXPECT_EQ(program.path.records[0].motion, MotionKind::Rapid);
    EXPECT_EQ(rewriteApt(program, program.path.records).value(), program.text);
}

TEST(ParseApt, CollectsUpToTwentyErrors) {
    std::string text = "FEDRAT/60\n";
    for (int i = 0; i < 30; ++i) {
        text += "GOTO/1,2\n";
    }
    Result<AptProgram> program = parseApt(text, "many.cls");
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().where.line, 2);
    EXPECT_EQ(program.error().more.size(), 19u);
    EXPECT_EQ(program.error().more.back().where.line, 21);
}

TEST(ReadAptFile, ReadsTheClassicAptSample) {
    Result<AptProgram> program = readAptFile(kClDir / "classic_apt.apt");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto& records = program->path.records;
    ASSERT_EQ(records.size(), 8u);
    EXPECT_EQ(records[0].motion, MotionKind::Rapid);
    EXPECT_DOUBLE_EQ(records[1].feed, 10.0);
    EXPECT_EQ(records[3].line, 14); // the continued GOTO
    EXPECT_NEAR(records[3].axis.x(), 0.017452, 1e-6);
    EXPECT_DOUBLE_EQ(records[4].feed, 15.0);
    EXPECT_EQ(records[5].axis, records[4].axis); // GOTO/x,y,z keeps the axis
    EXPECT_DOUBLE_EQ(records[6].feed, 20.0);
    EXPECT_EQ(program->path.toolRadius, 4.0);
    EXPECT_FALSE(program->crlf);
}

TEST(ReadAptFile, ReadsTheNxClsfSample) {
    Result<AptProgram> program = readAptFile(kClDir / "nx_clsf_crlf.cls");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_EQ(program->path.records.size(), 32u);
    EXPECT_EQ(program->path.toolRadius, 5.0);
    EXPECT_TRUE(program->crlf);
    EXPECT_TRUE(program->path.warnings.empty());
    for (const toolpath::ClRecord& record : program->path.records) {
        EXPECT_NEAR(record.axis.norm(), 1.0, 1e-12);
    }
}

TEST(ReadAptFile, ReportsAMissingFile) {
    Result<AptProgram> program = readAptFile(kClDir / "does_not_exist.cls");
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().code, ErrorCode::FileNotFound);
}

} // namespace
} // namespace bladeaxis::io::cl

namespace bladeaxis::io::cl {
namespace {

// A CL file cut short still parses statement by statement; the missing FINI (APT) or
// END-OF-PATH (NX CLSF) is what tells.
TEST(ParseApt, FileWithoutFiniOrEndOfPathIsReadWithATruncationWarning) {
    const auto complete =
        parseApt("MULTAX\nFEDRAT/MMPM,600\nGOTO/0,0,9,0,0,1\nGOTO/1,0,9,0,0,1\nFINI\n", "c.cls");
    ASSERT_TRUE(complete.has_value());
    EXPECT_TRUE(complete->path.warnings.empty());
    const auto clsf = parseApt("MULTAX\nFEDRAT/MMPM,600\nGOTO/0,0,9,0,0,1\nEND-OF-PATH\n", "c.cls");
    ASSERT_TRUE(clsf.has_value());
    EXPECT_TRUE(clsf->path.warnings.empty());
    const auto truncated =
        parseApt("MULTAX\nFEDRAT/MMPM,600\nGOTO/0,0,9,0,0,1\nGOTO/1,0,9,0,0,1\n", "c.cls");
    ASSERT_TRUE(truncated.has_value());
    ASSERT_EQ(truncated->path.warnings.size(), 1u);
    EXPECT_NE(truncated->path.warnings[0].find("may be truncated"), std::string::npos);
    EXPECT_EQ(truncated->path.warnings[0].rfind("c.cls:4:", 0), 0u) << "names the last line";
}

} // namespace
} // namespace bladeaxis::io::cl

#include "core/io/nc/gcode_reader.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using kinematics::defaultBladeMachine;
using test::parseSample;
using toolpath::MotionKind;
using units::degToRad;

constexpr double kEps = 1e-12;

void expectAxes(const toolpath::ClRecord& record, double x, double y, double z, double aDeg,
                double bDeg) {
    ASSERT_TRUE(record.axes.has_value());
    EXPECT_NEAR(record.axes->x, x, kEps) << "line " << record.line;
    EXPECT_NEAR(record.axes->y, y, kEps) << "line " << record.line;
    EXPECT_NEAR(record.axes->z, z, kEps) << "line " << record.line;
    EXPECT_NEAR(record.axes->a, degToRad(aDeg), kEps) << "line " << record.line;
    EXPECT_NEAR(record.axes->b, degToRad(bDeg), kEps) << "line " << record.line;
}

Result<GcodeProgram> parse(std::string_view text) {
    return parseGcode(text, "t.nc", test::wholeUnitsMachine(), test::inDegrees());
}

TEST(GcodeReader, FanucProgramGivesOneRecordPerMoveOnceAllAxesAreKnown) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    const auto& records = program.path.records;
    ASSERT_EQ(records.size(), 8u);
    const std::vector<int> lines{8, 9, 10, 11, 12, 13, 14, 15};
    for (std::size_t i = 0; i < records.size(); ++i) {
        EXPECT_EQ(records[i].line, lines[i]);
    }
    EXPECT_EQ(records[0].motion, MotionKind::Rapid);
    EXPECT_EQ(records[2].motion, MotionKind::Feed);
    EXPECT_EQ(records[7].motion, MotionKind::Rapid);
    expectAxes(records[0], -10.0, 0.0, 100.0, 0.0, 0.0);
    expectAxes(records[4], 10.0, 2.0, 5.0, 5.0, 0.0);  // modal X, Z and A
    expectAxes(records[5], 10.0, 2.0, 5.0, 10.0, 0.0); // block delete is active
    EXPECT_TRUE(program.path.warnings.empty());
}

TEST(GcodeReader, FeedsAreMillimetresPerSecondAndRapidsHaveNone) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    const auto& records = program.path.records;
    EXPECT_DOUBLE_EQ(records[0].feed, 0.0);
    EXPECT_DOUBLE_EQ(records[2].feed, 600.0 / 60.0);
    EXPECT_DOUBLE_EQ(records[3].feed, 1200.0 / 60.0);
    EXPECT_DOUBLE_EQ(records[4].feed, 1200.0 / 60.0); // F is modal
}

TEST(GcodeReader, TipAndAxisComeFromForwardKinematics) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    const toolpath::ClRecord& record = program.path.records[3]; // X10 Y1.5 Z5 A5 B0
    const double c = std::cos(degToRad(5.0));
    const double s = std::sin(degToRad(5.0));
    EXPECT_NEAR(record.tip.x(), 10.0, kEps);
    EXPECT_NEAR(record.tip.y(), c * 1.5 + s * 5.0, kEps);
    EXPECT_NEAR(record.tip.z(), -s * 1.5 + c * 5.0, kEps);
    EXPECT_NEAR(record.axis.y(), s, kEps);
    EXPECT_NEAR(record.axis.z(), c, kEps);
}

TEST(GcodeReader, IncrementalWordsAddToThePreviousPosition) {
    const GcodeProgram program = parseSample("incremental_g91.nc");
    const auto& records = program.path.records;
    ASSERT_EQ(records.size(), 5u);
    expectAxes(records[0], 10.0, 20.0, 30.0, 0.0, 0.0);
    expectAxes(records[1], 11.0, 18.0, 30.0, 90.0, 0.0);
    expectAxes(records[2], 11.5, 18.0, 29.0, 90.0, 0.0);
    expectAxes(records[3], 11.5, 18.0, 29.0, 45.0, 0.0);
    expectAxes(records[4], 11.5, 18.0, 100.0, 45.0, 0.0); // back in G90
}

TEST(GcodeReader, InchValuesAndFeedsAreConvertedToMillimetres) {
    const GcodeProgram program = parseSample("inch_g20.nc");
    const auto& records = program.path.records;
    ASSERT_EQ(records.size(), 4u);
    expectAxes(records[0], 25.4, 50.8, 76.2, 0.0, 0.0);
    expectAxes(records[1], 38.1, 50.8, 76.2, 30.0, 0.0); // A stays in degrees
    expectAxes(records[2], 38.1, -6.35, 76.2, 30.0, 0.0);
    EXPECT_NEAR(records[1].feed, 10.0 * 25.4 / 60.0, kEps);
}

TEST(GcodeReader, InverseTimeFeedBecomesTipChordOverBlockDuration) {
    const GcodeProgram program = parseSample("inverse_time_g93.nc");
    const auto& records = program.path.records;
    ASSERT_EQ(records.size(), 4u);
    EXPECT_NEAR(records[1].feed, 5.0, kEps); // chord 5 mm, F60: 1 s
    EXPECT_NEAR(records[2].feed, 6.0, kEps); // chord 12 mm, F30: 2 s
    EXPECT_DOUBLE_EQ(records[3].feed, 0.0);  // rapid
}

TEST(GcodeReader, AcceptsLowerCaseRunTogetherWordsAndBareDecimalPoints) {
    const GcodeProgram program = parseSample("compact_lowercase.nc");
    const auto& records = program.path.records;
    ASSERT_EQ(records.size(), 3u);
    expectAxes(records[1], 0.5, -0.25, 1.5, 0.75, 0.0);
    expectAxes(records[2], 1.25, 0.5, 1.5, 0.75, 0.0);
    EXPECT_NEAR(records[1].feed, 1000.0 / 60.0, kEps);
}

TEST(GcodeReader, UnprogrammedBIsZeroWithAWarning) {
    const auto program = parse("G0 X1 Y2 Z3 A4\nG1 X2 F100\nM30\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_DOUBLE_EQ(program->path.records[0].axes->b, 0.0);
    ASSERT_EQ(program->path.warnings.size(), 1u);
    EXPECT_NE(program->path.warnings[0].find("t.nc:1"), std::string::npos);
}

TEST(GcodeReader, ConstantCAndModalNoOpCodesAreAccepted) {
    const auto program = parse("G17 G40 G49 G80 G54.1 G43 H1\nG0 X0 Y0 Z9 A0 B0 C0\n"
                               "G1 X1 C0. F100 M8\nG64 X2\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_EQ(program->path.records.size(), 3u);
}

// Fanuc's tool centre point control G43.4 programs the tip in the workpiece frame, as TRAORI
// and M128 do; G49 ends it. Read as machine axes instead, the tip would be turned by A.
TEST(GcodeReader, ToolCentrePointControlG434ProgramsTheTipInTheWorkpieceFrame) {
    const auto program = parse("G21 G90 G94\nG43.4 H1\nG1 X10. Y20. Z5. A30. B10. F1000.\n"
                               "G49\nG1 X11.\nM30\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    ASSERT_EQ(program->path.records.size(), 2u);
    const toolpath::ClRecord& tcp = program->path.records[0];
    EXPECT_LT((tcp.tip - Vec3(10.0, 20.0, 5.0)).norm(), 1e-12);
    const Vec3 axis = rotationX(-units::degToRad(30.0)) *
                      Vec3(std::sin(units::degToRad(10.0)), 0.0, std::cos(units::degToRad(10.0)));
    EXPECT_LT((tcp.axis - axis).norm(), 1e-12);
    EXPECT_NE(program->sources[0].flags & kToolTip, 0);
    // After G49 X Y Z are machine axes again: the table's 30 deg turns the tip.
    EXPECT_EQ(program->sources[1].flags & kToolTip, 0);
    const Vec3 turned = rotationX(-units::degToRad(30.0)) * Vec3(11.0, 20.0, 5.0);
    EXPECT_LT((program->path.records[1].tip - turned).norm(), 1e-12);
}

TEST(GcodeReader, ToolCentrePointControlWithAnIjkToolAxisIsRefused) {
    const auto program = parse("G21 G90 G94\nG43.5 H1\nG1 X10. Y20. Z5. A30. B10. F1000.\n");
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().where.line, 2);
    EXPECT_NE(program.error().message.find("G43.5"), std::string::npos);
}

TEST(GcodeReader, BlanksBetweenLetterAndNumberAreAccepted) {
    const auto program = parse("G0 X 1.5 Y 2 Z3 A 4\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_DOUBLE_EQ(program->path.records[0].axes->x, 1.5);
}

TEST(GcodeReader, ReferenceReturnForgetsTheAxesItNames) {
    const auto program = parse("G0 X0 Y0 Z9 A0 B0\nG91 G28 Z0\nG90 G1 X5 F100\n");
    ASSERT_FALSE(program.has_value());
    EXPECT_NE(program.error().toString().find("t.nc:3:"), std::string::npos);
}

TEST(GcodeReader, ErrorsNameFileLineColumnAndWhatWasExpected) {
    const auto program = parse("G0 X0 Y0 Z0 A0\nG1 X F100\n");
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().code, ErrorCode::Parse);
    EXPECT_EQ(program.error().toString(), "t.nc:2:6: parse error: expected a number after 'X'");
}

TEST(GcodeReader, CollectsFurtherErrorsUpToTheLimit) {
    std::string text = "G0 X0 Y0 Z0 A0\n";
    for (int i = 0; i < 30; ++i) {
        text += "G1 X1.2.3 F100\n";
    }
    const auto program = parse(text);
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().where.line, 2);
    EXPECT_EQ(program.error().more.size(), static_cast<std::size_t>(kMaxParseErrors - 1));
    EXPECT_EQ(program.error().more.back().where.line, kMaxParseErrors + 1);
}

TEST(GcodeReader, MissingFileIsFileNotFound) {
    const auto program = readGcodeFile(test::sampleDir() / "missing.nc", defaultBladeMachine());
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().code, ErrorCode::FileNotFound);
}

TEST(GcodeReader, RecordSourcesPointAtTheAxisWords) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    const RecordSource& source = program.sources[3]; // "N80 X10.000 Y1.500 A5.000 F1200."
    const std::string_view text = program.text;
    EXPECT_EQ(text.substr(source.lineBegin + source.wordBegin[0], source.wordLength[0]), "10.000");
    EXPECT_EQ(text.substr(source.lineBegin + source.wordBegin[3], source.wordLength[3]), "5.000");
    EXPECT_FALSE(source.hasWord(2));
    EXPECT_EQ(sizeof(RecordSource), 24u);
}

} // namespace
} // namespace bladeaxis::io::nc

namespace bladeaxis::io::nc {
namespace {

// A program cut short still parses block by block; the missing M2/M30 is what tells.
TEST(GcodeReader, ProgramWithoutM30IsReadWithATruncationWarningOnItsLastLine) {
    const auto complete = parseGcode("G21 G90 G94\nG1 X0 Y0 Z10 A0 B5 F1000\nX1\nM30\n", "t.nc",
                                     kinematics::defaultBladeMachine(), test::inDegrees());
    ASSERT_TRUE(complete.has_value());
    EXPECT_TRUE(complete->path.warnings.empty());
    const auto lowercaseM2 = parseGcode("g21 g90 g94\ng1 x0 y0 z10 a0 b5 f1000\nm2\n", "t.nc",
                                        kinematics::defaultBladeMachine(), test::inDegrees());
    ASSERT_TRUE(lowercaseM2.has_value());
    EXPECT_TRUE(lowercaseM2->path.warnings.empty());
    const auto truncated = parseGcode("G21 G90 G94\nG1 X0 Y0 Z10 A0 B5 F1000\nX1\n", "t.nc",
                                      kinematics::defaultBladeMachine(), test::inDegrees());
    ASSERT_TRUE(truncated.has_value());
    ASSERT_EQ(truncated->path.warnings.size(), 1u);
    EXPECT_NE(truncated->path.warnings[0].find("t.nc:3"), std::string::npos);
    EXPECT_NE(truncated->path.warnings[0].find("may be truncated"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io::nc

// Shop programs that the reader once read wrongly without a word: rotary words in radians,
// numbers without a decimal point, subprograms, text after the program end, editor artefacts.
// Each is read right, or refused naming its line and what to do.

#include "core/io/nc/gcode_writer.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using kinematics::defaultBladeMachine;
using units::degToRad;

constexpr double kEps = 1e-9;

Result<GcodeProgram> parse(std::string_view text, const ReadOptions& options = {},
                           const kinematics::MachineModel& machine = defaultBladeMachine()) {
    return parseGcode(text, "shop.nc", machine, options);
}

ReadOptions withUnit(AngleUnit unit) {
    ReadOptions options;
    options.angleUnit = unit;
    return options;
}

kinematics::MachineModel machineReading(kinematics::IntegerWords rule) {
    kinematics::MachineModel machine = defaultBladeMachine();
    machine.numbers.integerWords = rule;
    return machine;
}

void expectSameRecords(const GcodeProgram& a, const GcodeProgram& b, double tolerance) {
    ASSERT_EQ(a.path.records.size(), b.path.records.size());
    for (std::size_t i = 0; i < a.path.records.size(); ++i) {
        EXPECT_LT((a.path.records[i].tip - b.path.records[i].tip).norm(), tolerance) << i;
        EXPECT_LT((a.path.records[i].axis - b.path.records[i].axis).norm(), tolerance) << i;
    }
}

constexpr std::string_view kDegrees = "G21 G90 G94\nG0 X0. Y0. Z50. A0. B5.\n"
                                      "G1 X1.5 A30. F1000.\nX2.5 A60.\nM30\n";
constexpr std::string_view kRadians = "G21 G90 G94\nG0 X0. Y0. Z50. A0. B0.0872664626\n"
                                      "G1 X1.5 A0.5235987756 F1000.\nX2.5 A1.0471975512\nM30\n";

TEST(GcodeShopPrograms, RadiansWithTheAngleUnitReadLikeTheDegreeProgram) {
    const auto degrees = parse(kDegrees, withUnit(AngleUnit::Degrees));
    const auto radians = parse(kRadians, withUnit(AngleUnit::Radians));
    ASSERT_TRUE(degrees && radians);
    expectSameRecords(*degrees, *radians, 1e-9);
    EXPECT_EQ(radians->angleUnit, AngleUnit::Radians);
}

TEST(GcodeShopPrograms, RotaryWordsWithinTwoPiAreRefusedAsAmbiguousNamingTheOption) {
    const auto program = parse(kRadians);
    ASSERT_FALSE(program.has_value());
    // Named at the largest word, A1.0471975512 on line 4: the word that could be either unit.
    EXPECT_EQ(program.error().where.line, 4);
    EXPECT_EQ(program.error().where.column, 6);
    EXPECT_NE(program.error().message.find("ambiguous"), std::string::npos);
    EXPECT_NE(program.error().message.find("--angle-unit"), std::string::npos);
}

TEST(GcodeShopPrograms, AHeaderCommentThatNamesTheAngleUnitDecidesIt) {
    const auto declared = parse("(ANGLES IN RADIANS)\n" + std::string(kRadians));
    ASSERT_TRUE(declared.has_value()) << declared.error().toString();
    EXPECT_EQ(declared->angleUnit, AngleUnit::Radians);
    const auto degrees = parse("; rotary unit: deg\n" + std::string(kDegrees));
    ASSERT_TRUE(degrees.has_value()) << degrees.error().toString();
    EXPECT_EQ(degrees->angleUnit, AngleUnit::Degrees);
    // Mentions of degrees that do not talk about the rotary words' unit declare nothing.
    EXPECT_FALSE(parse("(BALL R=4, B=5 deg, lead 15 deg)\n" + std::string(kRadians)));
}

TEST(GcodeShopPrograms, ARotaryWordBeyondTwoPiCanOnlyBeDegrees) {
    const auto program = parse("G21 G90 G94\nG0 X0. Y0. Z50. A0. B5.\nG1 X1. A360. F1000.\nM30\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_EQ(program->angleUnit, AngleUnit::Degrees);
    EXPECT_NEAR(program->path.records.back().axes->a, degToRad(360.0), kEps);
}

TEST(GcodeShopPrograms, AProgramWhoseRotaryWordsAreAllZeroNeedsNoUnit) {
    EXPECT_TRUE(parse("G21 G90 G94\nG0 X0. Y0. Z50. A0. B0.\nG1 X1. F1000.\nM30\n"));
}

TEST(GcodeShopPrograms, TheWriterKeepsRadiansAndTheProgramReadsBack) {
    const auto program = parse(kRadians, withUnit(AngleUnit::Radians));
    ASSERT_TRUE(program.has_value());
    auto axes = test::axesOf(*program);
    axes[2].a += degToRad(10.0);
    const auto text = rewriteGcode(*program, axes, defaultBladeMachine());
    ASSERT_TRUE(text.has_value());
    EXPECT_EQ(test::lineOf(*text, 4), "X2.5 A1.2217304764");
    const auto back = parse(*text, withUnit(AngleUnit::Radians));
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->path.records[2].axes->a, axes[2].a, 1e-10);
}

TEST(GcodeShopPrograms, IntegerWordsCountLeastInputIncrementsOnAFanucStyleControl) {
    const auto machine = machineReading(kinematics::IntegerWords::Increments);
    const auto program = parse("G21 G90 G94\nG0 X0 Y0 Z50000 A0 B5000\nG1 X1000 A90000 F1000\n"
                               "G20\nX10000\nM30\n",
                               {}, machine);
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto& records = program->path.records;
    EXPECT_NEAR(records[0].axes->z, 50.0, kEps);
    EXPECT_NEAR(records[0].axes->b, degToRad(5.0), kEps);
    EXPECT_NEAR(records[1].axes->x, 1.0, kEps);
    EXPECT_NEAR(records[1].axes->a, degToRad(90.0), kEps);
    EXPECT_NEAR(records[2].axes->x, 25.4, kEps); // 10000 x 0.0001 inch
    EXPECT_NEAR(records[1].feed, 1000.0 / 60.0, kEps) << "F is not an axis word";
}

TEST(GcodeShopPrograms, IntegerWordsAreWholeUnitsWhenTheMachineSaysSo) {
    const auto program = parse("G21 G90 G94\nG0 X0 Y0 Z50 A0 B5\nG1 X1000 A400 F1000\nM30\n", {},
                               machineReading(kinematics::IntegerWords::Units));
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_NEAR(program->path.records[1].axes->x, 1000.0, kEps);
}

TEST(GcodeShopPrograms, MixedDecimalStylesAreRefusedNamingTheFirstLineOfEach) {
    const auto program = parse("G21 G90 G94\nG0 X0 Y0 Z50. A0 B5.\nG1 X1000 A400. F1000\nM30\n");
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().where.line, 3);
    EXPECT_NE(program.error().message.find("with one at line 2"), std::string::npos);
    EXPECT_NE(program.error().message.find("integer_words"), std::string::npos);
}

TEST(GcodeShopPrograms, ARewriteOnAnIncrementsControlKeepsEachWordsStyle) {
    const auto machine = machineReading(kinematics::IntegerWords::Increments);
    const auto program =
        parse("G21 G90 G94\nG0 X0 Y0 Z50000 A0 B5000\nG1 X1000 A400000 F1000\nM30\n", {}, machine);
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    auto axes = test::axesOf(*program);
    axes[1].x = 1.25;
    axes[1].a = degToRad(410.5);
    const auto text = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(text.has_value());
    EXPECT_EQ(test::lineOf(*text, 3), "G1 X1250 A410500 F1000");
    const auto back = parse(*text, {}, machine);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->path.records[1].axes->x, 1.25, kEps);
}

TEST(GcodeShopPrograms, SubprogramCallsAndReturnsAreRefusedNamingTheLine) {
    for (const char* block : {"M98 P1000", "M99", "G65 P9010"}) {
        const auto program =
            parse(std::string(kDegrees.substr(0, kDegrees.size() - 4)) + block + "\nM30\n",
                  withUnit(AngleUnit::Degrees));
        ASSERT_FALSE(program.has_value()) << block;
        EXPECT_EQ(program.error().where.line, 5) << block;
    }
}

TEST(GcodeShopPrograms, ASubprogramBodyAfterTheEndIsRefusedButCommentsAreFine) {
    const std::string body = std::string(kDegrees) + "O2000\nG1 X9. A90.\nM99\n";
    const auto refused = parse(body, withUnit(AngleUnit::Degrees));
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().where.line, 6);
    EXPECT_NE(refused.error().message.find("line 5"), std::string::npos);
    const auto fine =
        parse(std::string(kDegrees) + "(END OF PROGRAM)\n\n%\n", withUnit(AngleUnit::Degrees));
    EXPECT_TRUE(fine.has_value());
}

TEST(GcodeShopPrograms, AByteOrderMarkAndCrlfReadLikePlainText) {
    const auto plain = parse(kDegrees, withUnit(AngleUnit::Degrees));
    std::string crlf;
    for (char c : kDegrees) {
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    }
    const auto marked = parse("\xEF\xBB\xBF" + crlf, withUnit(AngleUnit::Degrees));
    ASSERT_TRUE(plain && marked) << (marked ? "" : marked.error().toString());
    expectSameRecords(*plain, *marked, 0.0 + 1e-15);
    EXPECT_TRUE(marked->path.warnings.empty());
}

TEST(GcodeShopPrograms, AMissingEndIsReportedOnTheLastLineWithoutAFinalNewline) {
    const auto program = parse("G21 G90 G94\r\nG0 X0. Y0. Z50. A0. B5.\r\nG1 X1. A30. F1000.",
                               withUnit(AngleUnit::Degrees));
    ASSERT_TRUE(program.has_value());
    ASSERT_EQ(program->path.warnings.size(), 1u);
    EXPECT_NE(program->path.warnings[0].find("shop.nc:3"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io::nc

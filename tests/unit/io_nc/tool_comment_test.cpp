// The ball radius a post states in a header comment (Autodesk convention "D=8. CR=4."), so a
// program that says which cutter it was posted for needs no --tool-radius.

#include "core/io/nc/detail/tool_comment.h"

#include <gtest/gtest.h>

#include "gcode_test_support.h"

namespace bladeaxis::io::nc {
namespace {

using detail::toolInComment;

TEST(ToolComment, ReadsDiameterAndCornerRadiusOfTheAutodeskPostConvention) {
    const auto tool = toolInComment("(T1 D=8. CR=4. TAPER=0deg - ZMIN=-10. - ball end mill)");
    ASSERT_TRUE(tool.has_value());
    EXPECT_DOUBLE_EQ(tool->diameter, 8.0);
    EXPECT_DOUBLE_EQ(tool->cornerRadius, 4.0);
    EXPECT_TRUE(tool->isBallEnd());
    EXPECT_TRUE(toolInComment("; t2 d = 6 cr = 3").has_value()) << "spaces and case";
}

TEST(ToolComment, ReadsTheBallRadiusOfBladeAxisGeneratorsHeader) {
    const auto tool = toolInComment("(ball end R=8 mm, B=5 deg, lead 15 deg, 3 revolutions)");
    ASSERT_TRUE(tool.has_value());
    EXPECT_DOUBLE_EQ(tool->cornerRadius, 8.0);
    EXPECT_DOUBLE_EQ(tool->diameter, 16.0);
    EXPECT_TRUE(tool->isBallEnd());
    const auto sinumerik = toolInComment("; ball end R=2.5 mm, B=5 deg");
    ASSERT_TRUE(sinumerik.has_value());
    EXPECT_DOUBLE_EQ(sinumerik->cornerRadius, 2.5);
    EXPECT_FALSE(toolInComment("(ball end R=0 mm)").has_value());
}

TEST(ToolComment, ABullNoseIsNotABallEnd) {
    const auto tool = toolInComment("(T3 D=10. CR=1. - bull nose end mill)");
    ASSERT_TRUE(tool.has_value());
    EXPECT_FALSE(tool->isBallEnd());
}

TEST(ToolComment, OffsetNumbersLoneRadiiAndOtherKeysAreNotATool) {
    EXPECT_FALSE(toolInComment("(T1 | 8MM BALL | H1 | D1 | TOOL DIA. - 8.)").has_value());
    EXPECT_FALSE(toolInComment("(fillet R=8 mm, B=5 deg)").has_value()) << "R= without a ball";
    EXPECT_FALSE(toolInComment("(ball end R8 mm)").has_value()) << "a lone R8";
    EXPECT_FALSE(toolInComment("(ID=8. CR=4.)").has_value()) << "ID is not D";
    EXPECT_FALSE(toolInComment("G1 X1 D=8 CR=4").has_value()) << "not in a comment";
    EXPECT_FALSE(toolInComment("(D=abc CR=4.)").has_value());
}

GcodeProgram parseText(const std::string& text) {
    auto program =
        parseGcode(text, "header.nc", kinematics::defaultBladeMachine(), test::inDegrees());
    EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().toString());
    return program ? std::move(*program) : GcodeProgram{};
}

const std::string kMoves = "G1 X0. Y0. Z10. A0. B5. F1000.\nG1 X1. Y0. Z10. A10. B5.\nM30\n";

TEST(ToolComment, TheHeadersBallRadiusBecomesTheProgramsToolRadius) {
    const GcodeProgram program =
        parseText("(T1 D=8. CR=4. - ball end mill)\nG21 G90 G94\n" + kMoves);
    ASSERT_TRUE(program.path.toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*program.path.toolRadius, 4.0);
}

TEST(ToolComment, TheGeneratorsHeaderRadiusBecomesTheProgramsToolRadius) {
    const GcodeProgram program = parseText(
        "(BladeAxis synthetic blade program [naca-weak, seed 3])\n(ball end R=8 mm, B=5 deg, "
        "lead 15 deg, 3 revolutions)\nG21 G90 G94\n" +
        kMoves);
    ASSERT_TRUE(program.path.toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*program.path.toolRadius, 8.0);
    const GcodeProgram agreeing =
        parseText("(T1 D=16. CR=8.)\n(ball end R=8 mm)\nG21 G90 G94\n" + kMoves);
    ASSERT_TRUE(agreeing.path.toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*agreeing.path.toolRadius, 8.0);
    const GcodeProgram disagreeing =
        parseText("(T1 D=8. CR=4.)\n(ball end R=8 mm)\nG21 G90 G94\n" + kMoves);
    EXPECT_FALSE(disagreeing.path.toolRadius.has_value()) << "two radii: neither is used";
}

TEST(ToolComment, AnInchProgramsRadiusIsConvertedToMillimetres) {
    const GcodeProgram program = parseText(
        "(T1 D=0.5 CR=0.25)\nG20 G90 G94\nG1 X0. Y0. Z1. A0. B5. F40.\nG1 X0.1 Y0. Z1. A10. "
        "B5.\nM30\n");
    ASSERT_TRUE(program.path.toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*program.path.toolRadius, 6.35);
}

TEST(ToolComment, ABullNoseIsRecordedWithItsLineAndTwoDifferentBallsGiveAWarningAndNoRadius) {
    const GcodeProgram bull = parseText("(T3 D=10. CR=1.)\nG21 G90 G94\n" + kMoves);
    EXPECT_FALSE(bull.path.toolRadius.has_value());
    ASSERT_TRUE(bull.path.nonBallCutter.has_value());
    EXPECT_EQ(bull.path.nonBallCutter->line, 1);
    EXPECT_EQ(bull.path.nonBallCutter->statement, "(T3 D=10. CR=1.)");
    EXPECT_EQ(bull.path.nonBallCutter->cornerRadius, 1.0);
    const GcodeProgram two = parseText("(T1 D=8. CR=4.)\n(T2 D=6. CR=3.)\nG21 G90 G94\n" + kMoves);
    EXPECT_FALSE(two.path.toolRadius.has_value());
    ASSERT_FALSE(two.path.warnings.empty());
    EXPECT_NE(two.path.warnings.front().find("header.nc:2: the header names ball radii 4 (line 1) "
                                             "and 3"),
              std::string::npos)
        << two.path.warnings.front();
}

TEST(ToolComment, AToolNamedAfterTheFirstMoveIsNotTheHeaders) {
    const GcodeProgram program =
        parseText("G21 G90 G94\nG1 X0. Y0. Z10. A0. B5. F1000.\n(T1 D=8. CR=4.)\nG1 X1. Y0. Z10. "
                  "A10. B5.\nM30\n");
    EXPECT_FALSE(program.path.toolRadius.has_value());
}

} // namespace
} // namespace bladeaxis::io::nc

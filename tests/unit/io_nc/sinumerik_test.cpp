// Sinumerik 840D programs: the rotary word forms (DC, ACP, ACN, AC, IC), tool-tip programming
// (TRAORI), the instructions kept verbatim, the ones refused, and minimal-diff writing that
// keeps each word's form.

#include "core/io/nc/gcode_writer.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using kinematics::defaultBladeMachine;
using units::degToRad;

constexpr double kEps = 1e-9;

Result<GcodeProgram> parse(std::string_view text) {
    ReadOptions options;
    options.dialect = NcDialect::Sinumerik;
    return parseGcode(text, "blade.mpf", defaultBladeMachine(), options);
}

std::string header(std::string_view moves) {
    return "N10 G71 G90 G94\nN20 G0 X0 Y0 Z50 A=DC(350.0) B5\n" + std::string(moves) + "N90 M30\n";
}

std::vector<double> aDegrees(const GcodeProgram& program) {
    std::vector<double> a;
    for (const toolpath::ClRecord& record : program.path.records) {
        a.push_back(units::radToDeg(record.axes->a));
    }
    return a;
}

void expectNear(const std::vector<double>& actual, const std::vector<double>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_NEAR(actual[i], expected[i], 1e-9) << i;
    }
}

TEST(Sinumerik, DirectWordsTakeTheShorterWayAcrossZero) {
    const auto program = parse(header("N30 G1 X1 A=DC(10) F3000\nN40 X2 A=DC(340)\n"));
    ASSERT_TRUE(program) << program.error().toString();
    expectNear(aDegrees(*program), {350.0, 370.0, 340.0});
    EXPECT_EQ(program->dialect, NcDialect::Sinumerik);
}

TEST(Sinumerik, PositiveAndNegativeWordsTurnOnlyTheirWay) {
    const auto program = parse(header("N30 G1 X1 A=ACP(340) F3000\nN40 X2 A=ACN(350)\n"));
    ASSERT_TRUE(program) << program.error().toString();
    // ACP from 350 to 340 turns +350 deg; ACN back to 350 turns -350 deg.
    expectNear(aDegrees(*program), {350.0, 700.0, 350.0});
}

TEST(Sinumerik, IncrementalAndAbsoluteFunctionsOverrideTheDistanceMode) {
    const auto program = parse(header("N30 G1 X1 A=IC(-5) F3000\nN40 G91 X1 A=AC(100)\n"));
    ASSERT_TRUE(program) << program.error().toString();
    expectNear(aDegrees(*program), {350.0, 345.0, 100.0});
    EXPECT_NEAR(program->path.records[2].axes->x, 2.0, kEps); // G91 X1 from X1
}

TEST(Sinumerik, NumbersWithoutADecimalPointAreWholeUnits) {
    const auto program = parse(header("N30 G1 X1 Y2.5 A=DC(10) F3000\n"));
    ASSERT_TRUE(program) << program.error().toString();
    EXPECT_NEAR(program->path.records[1].axes->x, 1.0, kEps);
}

TEST(Sinumerik, TraoriProgramsTheTipInTheWorkpieceFrame) {
    const auto program =
        parse("N10 G71 G90 G94\nN12 TRAORI\nN20 G1 X1 Y2 Z3 A=DC(90) B10 F3000\nN30 TRAFOOF\n"
              "N40 G0 Z50\nN50 M30\n");
    ASSERT_TRUE(program) << program.error().toString();
    const toolpath::ClRecord& tip = program->path.records[0];
    EXPECT_LT((tip.tip - Vec3(1, 2, 3)).norm(), kEps);
    const Vec3 axis =
        kinematics::toolAxisFor(defaultBladeMachine().chain, degToRad(90.0), degToRad(10.0));
    EXPECT_LT((tip.axis - axis).norm(), kEps);
    EXPECT_NE(program->sources[0].flags & kToolTip, 0);
    // After TRAFOOF the machine's X Y Z again: the table's A = 90 deg turns the point.
    const kinematics::ToolPose machine =
        kinematics::forwardKinematics(defaultBladeMachine().chain, *program->path.records[1].axes);
    EXPECT_LT((program->path.records[1].tip - machine.tip).norm(), kEps);
    EXPECT_EQ(program->sources[1].flags & kToolTip, 0);
}

TEST(Sinumerik, SettingsCyclesMessagesAndToolNamesAreKept) {
    const auto program =
        parse("%_N_BLADE_MPF\n;$PATH=/_N_MPF_DIR\nN2 T=\"BALL_R8\" D1\nN4 M6\n"
              "N6 CYCLE832(0.01,_ORI_FINISH,1)\nN8 MSG(\"FINISH; (BLADE)\")\nN10 G642 SOFT FFWON "
              "ORIWKS\nN12 G71 G90 G94 G17 G500\nN20 G0 X0 Y0 Z50 A0 B5\nN30 G1 X1 F3000 ; cut\n"
              "N40 M17\n");
    ASSERT_TRUE(program) << program.error().toString();
    EXPECT_EQ(program->path.records.size(), 2u);
}

using test::BlockRefusal;

class SinumerikRefusal : public ::testing::TestWithParam<BlockRefusal> {};

TEST_P(SinumerikRefusal, NamesTheLineColumnAndWhatIsNotSupported) {
    const BlockRefusal& refusal = GetParam();
    test::expectRefused(parse(header(std::string(refusal.block) + "\n")), 3, refusal);
}

INSTANTIATE_TEST_SUITE_P(
    Blocks, SinumerikRefusal,
    ::testing::Values(
        BlockRefusal{"r_parameter", "N30 R1=5", 5, "R-parameters"},
        BlockRefusal{"parameter_in_word", "N30 G1 X=R1 F3000", 10, "R-parameters"},
        BlockRefusal{"expression", "N30 G1 X=10+R2 F3000", 12, "expression"},
        BlockRefusal{"frame", "N30 TRANS X10", 5, "frame"},
        BlockRefusal{"swivel_cycle", "N30 CYCLE800(1,\"TC1\",0)", 5, "frame"},
        BlockRefusal{"jump", "N30 GOTOF END", 5, "control flow"},
        BlockRefusal{"unknown_call", "N30 BLADE_FINISH", 5, "unknown Sinumerik instruction"},
        BlockRefusal{"orientation_vector", "N30 G1 X1 A3=0.5 F3000", 11, "orientation vector"},
        BlockRefusal{"incremental_linear", "N30 G1 X=IC(5) F3000", 10, "only A and B"},
        BlockRefusal{"direct_beyond_a_turn", "N30 G1 X1 A=DC(400) F3000", 16, "[0, 360)"},
        BlockRefusal{"iso_comment", "N30 G1 X1 (CUT) F3000", 11, "comments start with ';'"},
        BlockRefusal{"iso_inch", "N30 G20", 5, "G70/G71"},
        BlockRefusal{"arc", "N30 G2 X1 Y1 I1 J0", 5, "circular"}),
    test::refusalName);

TEST(Sinumerik, BlocksAfterM17AreRefusedAsASecondProgram) {
    const auto program = parse(header("N30 G1 X1 F3000\nN40 M17\nN50 G1 X2\n"));
    ASSERT_FALSE(program.has_value());
    EXPECT_NE(program.error().message.find("after the program end"), std::string::npos);
}

TEST(Sinumerik, RadiansAreRefusedBecauseTheControlReadsDegrees) {
    ReadOptions options;
    options.dialect = NcDialect::Sinumerik;
    options.angleUnit = AngleUnit::Radians;
    const auto program =
        parseGcode(header("N30 G1 X1 F3000\n"), "blade.mpf", defaultBladeMachine(), options);
    ASSERT_FALSE(program.has_value());
    EXPECT_NE(program.error().message.find("degrees"), std::string::npos);
}

std::vector<kinematics::MachineAxes> withA(const GcodeProgram& program,
                                           const std::vector<double>& degrees) {
    std::vector<kinematics::MachineAxes> axes = test::axesOf(program);
    for (std::size_t i = 0; i < degrees.size(); ++i) {
        axes[i].a = degToRad(degrees[i]);
    }
    return axes;
}

TEST(SinumerikWriting, DirectWordsStayDirectAndOtherLinesAreByteIdentical) {
    const std::string text = header("N30 G1 X1 A=DC(10.0) F3000 ; cut\nN40 X2 A=DC(340.0)\n");
    const auto program = parse(text);
    ASSERT_TRUE(program);
    const auto written =
        rewriteGcode(*program, withA(*program, {350.0, 365.0, 345.0}), defaultBladeMachine());
    ASSERT_TRUE(written) << written.error().toString();
    EXPECT_EQ(*written, header("N30 G1 X1 A=DC(5.0) F3000 ; cut\nN40 X2 A=DC(345.0)\n"));
    const auto reread = parse(*written);
    ASSERT_TRUE(reread);
    expectNear(aDegrees(*reread), {350.0, 365.0, 345.0});
}

TEST(SinumerikWriting, AMissingWordIsInsertedInTheFormTheProgramUses) {
    const auto program = parse(header("N30 G1 X1 A=DC(10.0) F3000\nN40 X2\n"));
    ASSERT_TRUE(program);
    const auto written =
        rewriteGcode(*program, withA(*program, {350.0, 370.0, 372.5}), defaultBladeMachine());
    ASSERT_TRUE(written) << written.error().toString();
    EXPECT_NE(written->find("N40 X2 A=DC(12.5)"), std::string::npos) << *written;
}

TEST(SinumerikWriting, AMoveAgainstAnAcpWordIsRefusedNamingTheLine) {
    const auto program = parse(header("N30 G1 X1 A=ACP(10.0) F3000\n"));
    ASSERT_TRUE(program);
    const auto written =
        rewriteGcode(*program, withA(*program, {350.0, 349.0}), defaultBladeMachine());
    ASSERT_FALSE(written.has_value());
    EXPECT_EQ(written.error().code, ErrorCode::CheckFailed);
    EXPECT_EQ(written.error().where.line, 3);
    EXPECT_NE(written.error().message.find("ACP"), std::string::npos);
}

TEST(SinumerikWriting, ToolTipBlocksTakeNewTipCoordinates) {
    const auto program =
        parse("N10 G71 G90 G94\nN12 TRAORI\nN20 G1 X1.0 Y2.0 Z3.0 A=DC(90) B10 F3000\nN30 M30\n");
    ASSERT_TRUE(program);
    std::vector<kinematics::MachineAxes> axes = test::axesOf(*program);
    axes[0].y = 2.5;
    const auto written = rewriteGcode(*program, axes, defaultBladeMachine());
    ASSERT_TRUE(written);
    EXPECT_NE(written->find("N20 G1 X1.0 Y2.5 Z3.0 A=DC(90) B10 F3000"), std::string::npos)
        << *written;
}

} // namespace
} // namespace bladeaxis::io::nc

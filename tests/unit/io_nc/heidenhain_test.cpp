// Heidenhain conversational programs: L blocks, FMAX / FAUTO feeds, M126 shortest-path rotary
// words, IA increments, TOOL DEF / TOOL CALL radius, tool-tip programming (M128, FUNCTION
// TCPM), the statements refused, and minimal-diff writing in Heidenhain's own words.

#include "core/io/nc/dialect.h"
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
    options.dialect = NcDialect::Heidenhain;
    return parseGcode(text, "blade.h", defaultBladeMachine(), options);
}

std::string program(std::string_view moves) {
    return "0 BEGIN PGM BLADE MM\n1 TOOL DEF 1 L+0 R+4\n2 TOOL CALL 1 Z S12000 F2400 DR+0.5\n"
           "3 L X+0 Y+0 Z+50 A+350.0 B+5 R0 FMAX\n" +
           std::string(moves) + "9 END PGM BLADE MM\n";
}

std::vector<double> aDegrees(const GcodeProgram& parsed) {
    std::vector<double> a;
    for (const toolpath::ClRecord& record : parsed.path.records) {
        a.push_back(units::radToDeg(record.axes->a));
    }
    return a;
}

TEST(Heidenhain, LinearBlocksWithFmaxFautoAndAModalFeed) {
    const auto parsed = program("4 L X+1 A+340.0 R0 FAUTO\n5 L X+2 F3000\n6 L X+3\n");
    const auto read = parse(parsed);
    ASSERT_TRUE(read) << read.error().toString();
    const auto& records = read->path.records;
    ASSERT_EQ(records.size(), 4u);
    EXPECT_EQ(records[0].motion, toolpath::MotionKind::Rapid);
    EXPECT_EQ(records[1].motion, toolpath::MotionKind::Feed);
    EXPECT_NEAR(records[1].feed, 2400.0 / 60.0, kEps); // FAUTO: the TOOL CALL's F
    EXPECT_NEAR(records[2].feed, 3000.0 / 60.0, kEps);
    EXPECT_NEAR(records[3].feed, 3000.0 / 60.0, kEps);
    EXPECT_NEAR(records[1].axes->a, degToRad(340.0), kEps); // without M126: the long way
}

TEST(Heidenhain, TheToolDefRadiusWithTheCallsDeltaIsTheBallRadius) {
    const auto read = parse(program("4 L X+1 R0 F3000\n"));
    ASSERT_TRUE(read) << read.error().toString();
    ASSERT_TRUE(read->path.toolRadius.has_value());
    EXPECT_NEAR(*read->path.toolRadius, 4.5, kEps);
}

TEST(Heidenhain, M126TakesTheShorterWayAndIaAddsAnIncrement) {
    const auto read = parse(program("4 L X+1 A+10.0 R0 F3000 M126\n5 L X+2 IA-15.5\n"));
    ASSERT_TRUE(read) << read.error().toString();
    const std::vector<double> a = aDegrees(*read);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_NEAR(a[1], 370.0, 1e-9);
    EXPECT_NEAR(a[2], 354.5, 1e-9);
    EXPECT_EQ(read->sources[1].rotaryForms[0], RotaryForm::Shortest);
    EXPECT_EQ(read->sources[2].rotaryForms[0], RotaryForm::Incremental);
}

TEST(Heidenhain, M128AndFunctionTcpmProgramTheTipInTheWorkpieceFrame) {
    for (const char* on : {"4 L X+1 Y+2 Z+3 A+90 B+10 R0 F3000 M128\n",
                           "4 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                           "5 L X+1 Y+2 Z+3 A+90 B+10 R0 F3000\n"}) {
        const auto read = parse(program(on));
        ASSERT_TRUE(read) << read.error().toString();
        const toolpath::ClRecord& record = read->path.records.back();
        EXPECT_LT((record.tip - Vec3(1, 2, 3)).norm(), kEps) << on;
        EXPECT_NE(read->sources.back().flags & kToolTip, 0) << on;
    }
}

using test::BlockRefusal;

class HeidenhainRefusal : public ::testing::TestWithParam<BlockRefusal> {};

TEST_P(HeidenhainRefusal, NamesTheLineColumnAndWhatIsNotSupported) {
    const BlockRefusal& refusal = GetParam();
    test::expectRefused(parse(program(std::string(refusal.block) + "\n")), 5, refusal);
}

INSTANTIATE_TEST_SUITE_P(
    Blocks, HeidenhainRefusal,
    ::testing::Values(
        BlockRefusal{"arc_centre", "4 CC X+0 Y+0", 3, "arcs"},
        BlockRefusal{"arc", "4 C X+1 Y+0 DR+", 3, "arcs"},
        BlockRefusal{"radius_compensation", "4 L X+1 RL F3000", 9, "radius compensation"},
        BlockRefusal{"datum_shift", "4 CYCL DEF 7.0 DATUM SHIFT", 8, "CYCL DEF 32"},
        BlockRefusal{"tilted_plane", "4 PLANE SPATIAL SPA+0 SPB+45 SPC+0", 3, "tilted"},
        BlockRefusal{"q_parameter", "4 Q1 = 5", 3, "Q parameters"},
        BlockRefusal{"label", "4 LBL 1", 3, "labels"},
        BlockRefusal{"incremental_linear", "4 L IX+1 F3000", 5, "incremental linear"},
        BlockRefusal{"feed_per_tooth", "4 L X+1 FZ0.1", 9, "per tooth"},
        BlockRefusal{"spatial_tcpm", "4 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS", 12, "SPAT"},
        BlockRefusal{"retract", "4 L M140 MB MAX", 5, "retraction"},
        BlockRefusal{"unknown", "4 TCH PROBE 400", 3, "unknown Heidenhain statement"},
        BlockRefusal{"tool_number_beyond_the_table", "4 TOOL DEF 2E94 L+0 R+4", 12, "tool number"},
        BlockRefusal{"fractional_tool_number", "4 TOOL CALL 1.5 Z S1000", 13, "tool number"}),
    test::refusalName);

TEST(Heidenhain, InchProgramsAreRefusedNamingTheUnit) {
    const auto read = parse("0 BEGIN PGM BLADE INCH\n1 L X+0 Y+0 Z+2 A+30 B+0 R0 F100\n");
    ASSERT_FALSE(read.has_value());
    EXPECT_EQ(read.error().where.line, 1);
    EXPECT_NE(read.error().message.find("INCH"), std::string::npos);
}

TEST(HeidenhainWriting, WordsKeepTheirSignAndInsertedWordsFollowHeidenhain) {
    const auto read = parse(program("4 L X+1.0 A+10.0 R0 F3000 M126\n5 L X+2.0 R0\n"));
    ASSERT_TRUE(read);
    std::vector<kinematics::MachineAxes> axes = test::axesOf(*read);
    axes[1].x = -0.5;
    axes[2].a = degToRad(372.5);
    const auto written = rewriteGcode(*read, axes, defaultBladeMachine());
    ASSERT_TRUE(written) << written.error().toString();
    EXPECT_EQ(*written, program("4 L X-0.5 A+10.0 R0 F3000 M126\n5 L X+2.0 A+12.5 R0\n"));
}

TEST(HeidenhainWriting, AnIncrementalRotaryWordIsWrittenAsAnIncrement) {
    const auto read = parse(program("4 L X+1 A+10.0 R0 F3000\n5 L X+2 IA+5.0\n"));
    ASSERT_TRUE(read);
    std::vector<kinematics::MachineAxes> axes = test::axesOf(*read);
    axes[2].a = degToRad(17.5);
    const auto written = rewriteGcode(*read, axes, defaultBladeMachine());
    ASSERT_TRUE(written) << written.error().toString();
    EXPECT_NE(written->find("5 L X+2 IA+7.5\n"), std::string::npos) << *written;
}

TEST(NcDialectDetection, ContentFirstThenTheExtension) {
    EXPECT_EQ(detectDialect("0 BEGIN PGM A MM\n", "a.nc").dialect, NcDialect::Heidenhain);
    EXPECT_EQ(detectDialect("N10 TRAORI\nN20 G1 X1\n", "a.nc").dialect, NcDialect::Sinumerik);
    EXPECT_EQ(detectDialect("N20 G1 X1 A=DC(10)\n", "a").dialect, NcDialect::Sinumerik);
    EXPECT_EQ(detectDialect("N20 G1 X1 A10.\n", "a.mpf").dialect, NcDialect::Sinumerik);
    EXPECT_EQ(detectDialect("N20 G1 X1 A10.\n", "A.H").dialect, NcDialect::Heidenhain);
    EXPECT_EQ(detectDialect("N20 G1 X1 A10.\n", "a.nc").dialect, NcDialect::Iso);
    const DetectedDialect contradicted = detectDialect("0 BEGIN PGM A MM\n", "a.mpf");
    EXPECT_EQ(contradicted.dialect, NcDialect::Heidenhain);
    ASSERT_TRUE(contradicted.warning.has_value());
    EXPECT_NE(contradicted.warning->find("sinumerik"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io::nc

namespace bladeaxis::io::nc {
namespace {

TEST(HeidenhainProgramEnd, EndPgmAfterM30IsTheSameEndNotASecondProgram) {
    const auto read = parse("0 BEGIN PGM BLADE MM\n1 TOOL DEF 1 L+0 R+4\n"
                            "2 L X+0 Y+0 Z+50 A+350.0 B+5 R0 FMAX\n3 L X+1 A+340.0 R0 F3000\n"
                            "4 L X+2 A+330.0 M30\n5 END PGM BLADE MM\n");
    ASSERT_TRUE(read) << read.error().toString();
    EXPECT_EQ(read->path.records.size(), 3U);
}

TEST(HeidenhainProgramEnd, AMoveAfterTheEndIsStillRefused) {
    const auto read = parse("0 BEGIN PGM BLADE MM\n1 TOOL DEF 1 L+0 R+4\n"
                            "2 L X+0 Y+0 Z+50 A+350.0 B+5 R0 FMAX\n3 L X+1 R0 F3000 M30\n"
                            "4 L X+2\n5 END PGM BLADE MM\n");
    ASSERT_FALSE(read);
    EXPECT_NE(read.error().message.find("after the program end"), std::string::npos);
    EXPECT_EQ(read.error().where.line, 5); // the file line of block 4
}

} // namespace
} // namespace bladeaxis::io::nc

#include "core/io/nc/gcode_writer.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using kinematics::defaultBladeMachine;
using kinematics::MachineAxes;
using test::axesOf;
using test::lineOf;
using test::parseSample;
using units::degToRad;

std::string rewrite(const GcodeProgram& program, const std::vector<MachineAxes>& axes,
                    const kinematics::MachineModel& machine = defaultBladeMachine()) {
    Result<std::string> text = rewriteGcode(program, axes, machine);
    EXPECT_TRUE(text.has_value()) << (text ? "" : text.error().toString());
    return text ? *text : std::string();
}

// Every line of `after` equals that of `before` except the listed 1-based lines.
void expectOnlyLinesChanged(const std::string& before, const std::string& after,
                            const std::vector<int>& changed) {
    const auto count = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
    ASSERT_EQ(count(before), count(after));
    for (int line = 1; line <= count(before) + 1; ++line) {
        const bool expectChange = std::find(changed.begin(), changed.end(), line) != changed.end();
        EXPECT_EQ(lineOf(before, line) != lineOf(after, line), expectChange) << "line " << line;
    }
}

TEST(GcodeWriter, OriginalAxesReproduceEverySampleByteForByte) {
    int samples = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sampleDir())) {
        if (entry.path().extension() != ".nc") {
            continue;
        }
        ++samples;
        const std::string name = entry.path().filename().string();
        const GcodeProgram program = parseSample(name);
        EXPECT_EQ(rewrite(program, axesOf(program)), test::readSample(name)) << name;
    }
    EXPECT_GE(samples, 7);
}

TEST(GcodeWriter, ChangedAOnOneRecordChangesOnlyThatWord) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    auto axes = axesOf(program);
    axes[3].a = degToRad(7.5);
    axes[4].a = degToRad(7.5); // the next block's A is modal: keep it equal so it stays untouched
    const std::string text = rewrite(program, axes);
    EXPECT_EQ(lineOf(text, 11), "N80 X10.000 Y1.500 A7.500 F1200.");
    expectOnlyLinesChanged(program.text, text, {11});
}

TEST(GcodeWriter, KeepsLineEndingsAndMissingFinalNewline) {
    const GcodeProgram program = parseSample("crlf_no_final_newline.nc");
    auto axes = axesOf(program);
    axes[2].x = 5.125;
    const std::string text = rewrite(program, axes);
    EXPECT_EQ(text, "O2000\r\nG21 G90 G94\r\nG0 X0.000 Y0.000 Z50.000 A0.000 B10.000\r\n"
                    "G1 Z10.000 F900.\r\nX5.125 A2.500 (CRLF)\r\nX10.000 A5.000\r\n"
                    "G0 Z50.000\r\nM30");
}

TEST(GcodeWriter, InsertsAMissingModalWordInCanonicalOrder) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    auto axes = axesOf(program);
    axes[4].z = 6.0;  // N90 has no Z word
    axes[4].x = 11.0; // nor an X word: X goes before Y
    const std::string text = rewrite(program, axes);
    EXPECT_EQ(lineOf(text, 12), "N90 X11.000 Y2.000 Z6.000 (MODAL X AND Z)");
    // N100 keeps the original X and Z, which now differ from the modal values in effect.
    EXPECT_EQ(lineOf(text, 13), "/N100 X10.000 Z5.000 A10.000");
    expectOnlyLinesChanged(program.text, text, {12, 13});
}

TEST(GcodeWriter, KeepsTheFileNumberStyle) {
    const GcodeProgram compact = parseSample("compact_lowercase.nc");
    auto axes = axesOf(compact);
    axes[1].x = 0.625;
    axes[1].z = 2.0;
    axes[1].a = degToRad(-0.5);
    EXPECT_EQ(lineOf(rewrite(compact, axes), 3), "g1x.625y-.25z+2.a-.5f1000");

    const GcodeProgram trimmed = parseSample("trimmed_zeros.nc");
    axes = axesOf(trimmed);
    axes[1].x = 10.5;
    axes[2].y = 4.0;
    axes[2].a = degToRad(16.1234);
    const std::string text = rewrite(trimmed, axes);
    EXPECT_EQ(lineOf(text, 3), "G1 X10.5 Y2.5 Z5.125 A15.25 F1500.");
    EXPECT_EQ(lineOf(text, 4), "X12.75 Y4. A16.1234");
}

TEST(GcodeWriter, IncrementalBlocksGetRecomputedIncrements) {
    const GcodeProgram program = parseSample("incremental_g91.nc");
    auto axes = axesOf(program);
    axes[1].x = 12.0; // was 11 (increment 1), the next block's X stays 11.5
    const std::string text = rewrite(program, axes);
    EXPECT_EQ(lineOf(text, 4), "G91 G1 X2.000 Y-2.000 A90.000 F500.");
    EXPECT_EQ(lineOf(text, 5), "X-0.500 Z-1.000");
    expectOnlyLinesChanged(program.text, text, {4, 5});
}

TEST(GcodeWriter, InchBlocksAreWrittenInInches) {
    const GcodeProgram program = parseSample("inch_g20.nc");
    auto axes = axesOf(program);
    axes[1].x = 40.0;
    axes[2].x = 40.0;
    EXPECT_EQ(lineOf(rewrite(program, axes), 4), "G1 X1.5748 A30.000 F10.");
}

TEST(GcodeWriter, ModuloAIsWrittenInZeroTo360) {
    kinematics::MachineModel machine = test::wholeUnitsMachine();
    machine.aMode = kinematics::RotaryMode::Modulo;
    const auto program =
        parseGcode("G0 X0 Y0 Z9 A350.000 B0\nG1 X1 A355.000 F100\n", "m.nc", machine);
    ASSERT_TRUE(program.has_value());
    auto axes = axesOf(*program);
    axes[1].a = degToRad(370.0); // unwrapped by the scheduler
    EXPECT_EQ(lineOf(rewrite(*program, axes, machine), 2), "G1 X1 A10.000 F100");
}

TEST(GcodeWriter, RewrittenProgramReadsBackWithTheNewAxes) {
    for (const char* name : {"fanuc_basic.nc", "incremental_g91.nc", "inch_g20.nc",
                             "compact_lowercase.nc", "crlf_no_final_newline.nc"}) {
        const GcodeProgram program = parseSample(name);
        auto axes = axesOf(program);
        for (std::size_t i = 0; i < axes.size(); ++i) {
            axes[i].x += 0.25 * static_cast<double>(i % 3);
            axes[i].z -= 0.5;
            axes[i].a += degToRad(1.25 * static_cast<double>(i));
        }
        const auto back =
            parseGcode(rewrite(program, axes), name, defaultBladeMachine(), test::inDegrees());
        ASSERT_TRUE(back.has_value()) << name << ": " << back.error().toString();
        ASSERT_EQ(back->path.records.size(), axes.size()) << name;
        for (std::size_t i = 0; i < axes.size(); ++i) {
            const MachineAxes& got = *back->path.records[i].axes;
            // Half the last digit: 0.0005 mm, or 0.00005 inch = 0.00127 mm.
            EXPECT_NEAR(got.x, axes[i].x, 1.3e-3) << name << " record " << i;
            EXPECT_NEAR(got.z, axes[i].z, 1.3e-3) << name << " record " << i;
            EXPECT_NEAR(got.a, axes[i].a, degToRad(1e-3)) << name << " record " << i;
        }
    }
}

TEST(GcodeWriter, RejectsWrongCountAndNonFiniteAxes) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    auto axes = axesOf(program);
    axes.pop_back();
    auto result = rewriteGcode(program, axes, defaultBladeMachine());
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);

    axes = axesOf(program);
    axes[2].y = std::nan("");
    result = rewriteGcode(program, axes, defaultBladeMachine());
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("newAxes[2].Y"), std::string::npos);
}

// A job re-schedules one pass: the records around it keep the axes they were read with.
TEST(GcodeWriter, APassRewriteGivesWhatAWholeRewriteWithTheOtherRecordsUnchangedGives) {
    const GcodeProgram program = parseSample("fanuc_basic.nc");
    auto axes = axesOf(program);
    for (std::size_t i = 2; i < 6; ++i) {
        axes[i].a += degToRad(1.5 * static_cast<double>(i));
        axes[i].z += 0.25;
    }
    const std::vector<MachineAxes> pass(axes.begin() + 2, axes.begin() + 6);
    const auto passOnly = rewriteGcodePass(program, 2, pass, defaultBladeMachine());
    ASSERT_TRUE(passOnly.has_value()) << passOnly.error().toString();
    EXPECT_EQ(*passOnly, rewrite(program, axes));
    EXPECT_NE(*passOnly, program.text);

    const auto beyond = rewriteGcodePass(program, axes.size() - 2, pass, defaultBladeMachine());
    ASSERT_FALSE(beyond.has_value());
    EXPECT_EQ(beyond.error().code, ErrorCode::InvalidArgument);
}

TEST(GcodeWriter, WriteFileRefusesToOverwriteTheInput) {
    const auto dir = std::filesystem::temp_directory_path() / "bladeaxis_gcode_writer_test";
    std::filesystem::create_directories(dir);
    const auto input = dir / "in.nc";
    ASSERT_TRUE(writeFileAtomically(input, test::readSample("fanuc_basic.nc")).has_value());
    const auto program = readGcodeFile(input, defaultBladeMachine());
    ASSERT_TRUE(program.has_value());
    const auto axes = axesOf(*program);
    EXPECT_FALSE(writeGcodeFile(input, *program, axes, defaultBladeMachine()).has_value());
    ASSERT_TRUE(writeGcodeFile(dir / "out.nc", *program, axes, defaultBladeMachine()));
    EXPECT_EQ(*readTextFile(dir / "out.nc"), program->text);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace bladeaxis::io::nc

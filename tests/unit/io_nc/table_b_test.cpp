// A machine whose rotary table turns about Y (B) carries the blade along Y; its head, where it
// tilts, turns about X (A). The reader maps such a program onto the engine's table-A chain and
// the writer maps the new axes back to the program's own words. The expected poses here come
// from the machine's chain written out directly, not from the mapping under test.

#include "core/io/nc/gcode_writer.h"
#include "core/kinematics/machine_file.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <string>

namespace bladeaxis::io::nc {
namespace {

using kinematics::AxisId;
using units::degToRad;

kinematics::MachineModel machineFile(const std::string& name) {
    const auto machine = kinematics::loadMachineFile(std::filesystem::path(BLADEAXIS_SOURCE_DIR) /
                                                     "resources/machines" / name);
    EXPECT_TRUE(machine) << machine.error().toString();
    return machine ? *machine : kinematics::defaultBladeMachine();
}

constexpr std::string_view kTiltedBlock = "G21 G90 G94\nG1 X10. Y20. Z5. A10. B30. F1000.\n"
                                          "Y21. B31.\nM30\n";

TEST(TableB, ABlockIsTheToolPoseOfATableAboutYAndAHeadAboutX) {
    const auto machine = machineFile("table_b_head_a.json");
    const auto program = parseGcode(kTiltedBlock, "b.nc", machine, test::inDegrees());
    ASSERT_TRUE(program) << program.error().toString();
    const toolpath::ClRecord& record = program->path.records.front();
    // +B turns the workpiece right-handed about +Y, +A tilts the spindle right-handed about +X;
    // the workpiece frame sees both through the table's inverse turn.
    const Mat3 toWorkpiece = rotationY(-degToRad(30.0));
    const Vec3 tip = toWorkpiece * Vec3(10.0, 20.0, 5.0);
    const Vec3 axis = toWorkpiece * (rotationX(degToRad(10.0)) * Vec3::UnitZ());
    EXPECT_LT((machine.toProgramFrame(record.tip) - tip).norm(), 1e-12);
    EXPECT_LT((machine.toProgramFrame(record.axis) - axis).norm(), 1e-12);
    // The engine's table is the program's B, its tilt the program's A turned the other way.
    ASSERT_TRUE(record.axes);
    EXPECT_NEAR(record.axes->a, degToRad(30.0), 1e-15);
    EXPECT_NEAR(record.axes->b, -degToRad(10.0), 1e-15);
    EXPECT_EQ(machine.letter(AxisId::A), 'B');
    EXPECT_EQ(machine.letter(AxisId::B), 'A');
}

TEST(TableB, TheWriterPutsTheTablesNewAngleInTheBWordAndTheLinearAxesInTheirOwnWords) {
    const auto machine = machineFile("table_b_head_a.json");
    const auto program = parseGcode(kTiltedBlock, "b.nc", machine, test::inDegrees());
    ASSERT_TRUE(program) << program.error().toString();
    std::vector<kinematics::MachineAxes> axes;
    for (const toolpath::ClRecord& record : program->path.records) {
        axes.push_back(*record.axes);
    }
    axes[1].a += degToRad(2.0); // the table turns 2 deg further
    axes[1].y += 1.5;           // the engine's y is the machine's -X
    const auto text = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(text) << text.error().toString();
    EXPECT_EQ(*text, "G21 G90 G94\nG1 X10. Y20. Z5. A10. B30. F1000.\nX8.5 Y21. B33.\nM30\n");
    // Read back, the written block is the pose the engine asked for.
    const auto reread = parseGcode(*text, "b.nc", machine, test::inDegrees());
    ASSERT_TRUE(reread) << reread.error().toString();
    EXPECT_NEAR(reread->path.records[1].axes->a, axes[1].a, 1e-12);
    EXPECT_NEAR(reread->path.records[1].axes->y, axes[1].y, 1e-12);
}

TEST(TableB, AFixedHeadRefusesAnAWordThatTiltsTheTool) {
    const auto machine = machineFile("table_b.json");
    const auto program = parseGcode("G21 G90 G94\nG1 X1. Y2. Z3. B4. F500.\nX2. A5.\nM30\n",
                                    "fixed.nc", machine, test::inDegrees());
    ASSERT_FALSE(program.has_value());
    EXPECT_EQ(program.error().where.line, 3);
    EXPECT_NE(program.error().message.find("fixed head (no A axis)"), std::string::npos)
        << program.error().message;
}

TEST(TableB, AFeedMoveNeedsTheTablesBWordNotAnAWord) {
    const auto machine = machineFile("table_b_head_a.json");
    const auto missingB = parseGcode("G21 G90 G94\nG1 X1. Y2. Z3. A4. F500.\nM30\n", "noB.nc",
                                     machine, test::inDegrees());
    ASSERT_FALSE(missingB.has_value());
    EXPECT_NE(missingB.error().message.find("expected X, Y, Z and B to be programmed"),
              std::string::npos)
        << missingB.error().message;
    // Without an A word the head stands at A = 0, with a warning naming A.
    const auto noTilt = parseGcode("G21 G90 G94\nG1 X1. Y2. Z3. B4. F500.\nM30\n", "noA.nc",
                                   machine, test::inDegrees());
    ASSERT_TRUE(noTilt) << noTilt.error().toString();
    ASSERT_FALSE(noTilt->path.warnings.empty());
    EXPECT_NE(noTilt->path.warnings.front().find("A = 0 assumed"), std::string::npos);
}

TEST(TableB, AModuloTableWritesItsBWordInsideOneTurn) {
    kinematics::MachineModel machine = machineFile("table_b.json");
    machine.aMode = kinematics::RotaryMode::Modulo;
    const auto program = parseGcode("G21 G90 G94\nG1 X1. Y2. Z3. B350. F500.\nY3. B355.\nM30\n",
                                    "modulo.nc", machine, test::inDegrees());
    ASSERT_TRUE(program) << program.error().toString();
    std::vector<kinematics::MachineAxes> axes;
    for (const toolpath::ClRecord& record : program->path.records) {
        axes.push_back(*record.axes);
    }
    axes[1].a = degToRad(365.0);
    const auto text = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(text) << text.error().toString();
    EXPECT_NE(text->find("Y3. B5."), std::string::npos) << *text;
}

// A Sinumerik program for a table-B machine programs the table as B=DC(..): the table's word
// takes the shorter way, and a re-scheduled block writes its new B in the same form.
TEST(TableB, ASinumerikTablesDirectBWordIsReadAndWrittenInItsForm) {
    const auto machine = machineFile("table_b.json");
    ReadOptions options;
    options.dialect = NcDialect::Sinumerik;
    const auto program =
        parseGcode("N10 G71 G90 G94\nN20 G1 X0 Y0 Z50 B=DC(350.0) F3000\nN30 Y1 B=DC(10)\n"
                   "N90 M30\n",
                   "blade.mpf", machine, options);
    ASSERT_TRUE(program) << program.error().toString();
    ASSERT_EQ(program->path.records.size(), 2u);
    EXPECT_NEAR(program->path.records[1].axes->a, degToRad(370.0), 1e-12);
    std::vector<kinematics::MachineAxes> axes{*program->path.records[0].axes,
                                              *program->path.records[1].axes};
    axes[1].a = degToRad(365.0);
    const auto text = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(text) << text.error().toString();
    EXPECT_NE(text->find("N30 Y1 B=DC(5)"), std::string::npos) << *text;
}

} // namespace
} // namespace bladeaxis::io::nc

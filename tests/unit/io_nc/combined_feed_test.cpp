// A control that reads G94 F over the combined axis move (Fanuc without tool-tip control): a
// block lasts sqrt(dX^2 + dY^2 + dZ^2 + dA^2 + dB^2) / F. The reader times the blocks so, and
// the writer gives a block whose A step changes the F that keeps its time.

#include "core/io/nc/gcode_writer.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using units::degToRad;

kinematics::MachineModel combinedFeedMachine() {
    kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    machine.feedMeaning = kinematics::FeedMeaning::CombinedAxes;
    return machine;
}

constexpr std::string_view kProgram = "G21 G90 G94\nG1 X0. Y0. Z5. A0. B0. F600.\nX3. A4.\n"
                                      "X6. A8.\nX9. A12.\nM30\n";

TEST(CombinedFeed, ABlockLastsItsCombinedMoveOverF) {
    const auto program = parseGcode(kProgram, "fanuc.nc", combinedFeedMachine(), test::inDegrees());
    ASSERT_TRUE(program) << program.error().toString();
    const auto& records = program->path.records;
    ASSERT_EQ(records.size(), 4u);
    // X3 A4: a move of 5 units at F600 lasts 0.5 s; the tip moves along its chord meanwhile.
    const double chord = (records[1].tip - records[0].tip).norm();
    EXPECT_NEAR(records[1].feed, chord / 0.5, 1e-9);
    EXPECT_NE(program->sources[1].flags & kCombinedFeed, 0);
    ASSERT_EQ(program->programmedFeeds.size(), records.size());
    EXPECT_DOUBLE_EQ(program->programmedFeeds[1], 600.0);
}

TEST(CombinedFeed, AChangedBlockGetsTheFeedThatKeepsItsTimeAndTheNextOneRestatesF) {
    const auto machine = combinedFeedMachine();
    const auto program = parseGcode(kProgram, "fanuc.nc", machine, test::inDegrees());
    ASSERT_TRUE(program);
    std::vector<kinematics::MachineAxes> axes = test::axesOf(*program);
    // X3 A0: a move of 3 units must still last 0.5 s: F360. X6 A8 from there is 8.544 units
    // long: F1025.3. X9 A12 is unchanged and states the program's F600 again.
    axes[1].a = 0.0;
    const auto written = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(written) << written.error().toString();
    EXPECT_EQ(*written, "G21 G90 G94\nG1 X0. Y0. Z5. A0. B0. F600.\nX3. A0. F360\n"
                        "X6. A8. F1025.3\nX9. A12. F600\nM30\n");
}

TEST(CombinedFeed, TheProgramsOwnFeedIsLeftAloneWhereNoBlockChanges) {
    const auto machine = combinedFeedMachine();
    const auto program = parseGcode(kProgram, "fanuc.nc", machine, test::inDegrees());
    ASSERT_TRUE(program);
    const auto written = rewriteGcode(*program, test::axesOf(*program), machine);
    ASSERT_TRUE(written);
    EXPECT_EQ(*written, kProgram);
}

TEST(CombinedFeed, APathMachineKeepsFAsWritten) {
    const auto machine = kinematics::defaultBladeMachine();
    const auto program = parseGcode(kProgram, "fanuc.nc", machine, test::inDegrees());
    ASSERT_TRUE(program);
    EXPECT_TRUE(program->programmedFeeds.empty());
    std::vector<kinematics::MachineAxes> axes = test::axesOf(*program);
    axes[1].a = 0.0;
    const auto written = rewriteGcode(*program, axes, machine);
    ASSERT_TRUE(written);
    EXPECT_EQ(written->find("F360"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io::nc

// Machine layouts other than the table-A / head-B blade machine: a rotary table A about X with a
// fixed head ("table_a", no B axis). The synthetic family posted for it (B = 0) re-schedules
// without reversals and with its ball centres kept; a program that tilts B is refused.

#include "core/blade/blade.h"
#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/kinematics/machine_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path tableAMachineFile() {
    return fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines/table_a.json";
}

TEST(MachineLayouts, AFixedHeadMachineFileHasNoBAxis) {
    const auto machine = kinematics::loadMachineFile(tableAMachineFile());
    ASSERT_TRUE(machine) << machine.error().toString();
    EXPECT_FALSE(machine->hasB);
    EXPECT_FALSE(machine->limit(kinematics::AxisId::B).hasTravel);
    const auto withB = kinematics::parseMachineJson(
        R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_a"}, "axes": {
        "X": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Y": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Z": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "A": {"velocity_deg_s": 1, "acceleration_deg_s2": 1, "jerk_deg_s3": 1},
        "B": {"velocity_deg_s": 1, "acceleration_deg_s2": 1, "jerk_deg_s3": 1}}})",
        "fixed_head.json");
    ASSERT_FALSE(withB.has_value());
    EXPECT_EQ(withB.error().code, ErrorCode::MachineFile);
    EXPECT_NE(withB.error().message.find("fixed head"), std::string::npos);
}

TEST(MachineLayouts, TheFamilyOnAFixedHeadMachineReschedulesWithoutReversals) {
    const auto machine = kinematics::loadMachineFile(tableAMachineFile());
    ASSERT_TRUE(machine);
    const auto family = blade::syntheticFamily(20261125, 8);
    ASSERT_TRUE(family) << family.error().message;
    int reversalsBefore = 0;
    for (blade::FamilyMember member : *family) {
        member.path.tiltB0 = 0.0; // the fixed head's tool stays in the plane normal to X
        const auto model = blade::Blade::create(member.blade);
        ASSERT_TRUE(model) << member.name;
        const auto generated = blade::generateHelicalPath(*model, member.path);
        ASSERT_TRUE(generated) << member.name << ": " << generated.error().message;
        JobSpec spec;
        spec.program = member.name + ".nc";
        spec.programText = gcodeText(generated->path, *machine, 3000.0, RotaryUnit::Degrees);
        spec.machineFile = tableAMachineFile();
        spec.toolRadius = member.path.toolRadius;
        const auto result = runQuietly(spec);
        ASSERT_TRUE(result) << member.name << ": " << result.error().toString();
        ASSERT_TRUE(result->rescheduled.has_value()) << member.name;
        reversalsBefore += result->original.aReversals.count;
        EXPECT_EQ(result->rescheduled->profile.aReversals.count, 0) << member.name;
        EXPECT_LT(result->rescheduled->maxCentreDeviationMm, 1e-3) << member.name;
        EXPECT_EQ(result->rescheduled->programText.find(" B0.1"), std::string::npos) << member.name;
    }
    EXPECT_GT(reversalsBefore, 0); // the family has reversals to remove
}

TEST(MachineLayouts, AProgramThatTiltsBIsRefusedOnAFixedHeadMachine) {
    JobSpec spec;
    spec.program = "tilted.nc";
    spec.programText = "G21 G90 G94\nG1 X0. Y0. Z5. A10. B5. F3000.\nX1. A11.\nM30\n";
    spec.machineFile = tableAMachineFile();
    spec.toolRadius = 4.0;
    const auto result = runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Parse);
    EXPECT_EQ(result.error().where.line, 2);
    EXPECT_NE(result.error().message.find("fixed head (no B axis)"), std::string::npos)
        << result.error().message;
}

} // namespace
} // namespace bladeaxis::job::test

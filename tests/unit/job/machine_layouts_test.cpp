// Machine layouts other than the table-A / head-B blade machine: a rotary table A about X with a
// fixed head ("table_a", no B axis), and a rotary table B about Y with a head tilting about X
// ("table_b_head_a") or a fixed one ("table_b"). The synthetic family posted for each
// re-schedules without reversals and with its ball centres kept; a program that tilts a fixed
// head is refused.

#include "core/blade/blade.h"
#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/io/cl/apt_reader.h"
#include "core/kinematics/kinematics.h"
#include "core/kinematics/machine_file.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path tableAMachineFile() {
    return fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines/table_a.json";
}

fs::path shippedMachine(const std::string& name) {
    return fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines" / name;
}

// The family member's helical pass, generated in the engine's frame (blade along x). A fixed
// head keeps the tool in the plane normal to the table's axis.
toolpath::Toolpath familyPass(blade::FamilyMember member, bool fixedHead) {
    if (fixedHead) {
        member.path.tiltB0 = 0.0;
    }
    const auto model = blade::Blade::create(member.blade);
    EXPECT_TRUE(model) << member.name;
    const auto generated = blade::generateHelicalPath(*model, member.path);
    EXPECT_TRUE(generated) << member.name;
    return generated ? generated->path : toolpath::Toolpath{};
}

TEST(MachineLayouts, AFixedHeadMachineFileHasNoBAxis) {
    const auto machine = kinematics::loadMachineFile(tableAMachineFile());
    ASSERT_TRUE(machine) << machine.error().toString();
    EXPECT_FALSE(machine->hasB());
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

// On a table-B machine the family's blade lies along Y and the table's word is B: the
// re-scheduled program turns B monotonically, keeps the ball centres and stays in the travel.
TEST(MachineLayouts, TheFamilyOnTableBMachinesReschedulesTheBWordWithoutReversals) {
    for (const std::string name : {"table_b_head_a.json", "table_b.json"}) {
        const auto machine = kinematics::loadMachineFile(shippedMachine(name));
        ASSERT_TRUE(machine) << machine.error().toString();
        const auto family = blade::syntheticFamily(20261126, 6);
        ASSERT_TRUE(family) << family.error().message;
        int reversalsBefore = 0;
        for (const blade::FamilyMember& member : *family) {
            const toolpath::Toolpath pass = familyPass(member, !machine->hasB());
            JobSpec spec;
            spec.program = member.name + ".nc";
            spec.programText = gcodeText(pass, *machine, 3000.0, RotaryUnit::Degrees);
            spec.machineFile = shippedMachine(name);
            spec.toolRadius = member.path.toolRadius;
            const auto result = runQuietly(spec);
            ASSERT_TRUE(result) << name << " " << member.name << ": " << result.error().toString();
            ASSERT_TRUE(result->rescheduled.has_value()) << member.name;
            reversalsBefore += result->original.aReversals.count;
            EXPECT_EQ(result->rescheduled->profile.aReversals.count, 0) << name << member.name;
            EXPECT_LT(result->rescheduled->maxCentreDeviationMm, 1e-3) << name << member.name;
            const std::string& written = result->rescheduled->programText;
            EXPECT_NE(written, *spec.programText) << name << member.name;
            if (!machine->hasB()) {
                EXPECT_EQ(written.find(" A0.1"), std::string::npos) << name << member.name;
            }
        }
        EXPECT_GT(reversalsBefore, 0) << name; // the family has reversals to remove
    }
}

// CL data for a table-B machine give the blade along Y of the workpiece frame; the job turns it
// into the engine's frame and the written CL back, so re-reading the output gives the same
// ball centres in the program's frame.
TEST(MachineLayouts, ClDataForATableBMachineAreReadAndWrittenInTheProgramsFrame) {
    const auto machine = kinematics::loadMachineFile(shippedMachine("table_b_head_a.json"));
    ASSERT_TRUE(machine);
    const auto family = blade::syntheticFamily(20261126, 2);
    ASSERT_TRUE(family);
    const blade::FamilyMember& member = family->front();
    toolpath::Toolpath pass = familyPass(member, false);
    for (toolpath::ClRecord& record : pass.records) { // as the CAM posts it: blade along Y
        record.tip = machine->toProgramFrame(record.tip);
        record.axis = machine->toProgramFrame(record.axis);
    }
    JobSpec spec;
    spec.program = member.name + ".cl";
    spec.programText = aptText(pass, member.path.toolRadius, 3000.0);
    spec.machineFile = shippedMachine("table_b_head_a.json");
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result) << result.error().toString();
    ASSERT_TRUE(result->rescheduled.has_value());
    EXPECT_GT(result->original.aReversals.count, 0);
    EXPECT_EQ(result->rescheduled->profile.aReversals.count, 0);
    EXPECT_LT(result->rescheduled->maxCentreDeviationMm, 1e-3);
    // Read without any machine, the written CL keeps every ball centre of the input's frame.
    const auto before = io::cl::parseApt(*spec.programText, "in.cl");
    const auto after = io::cl::parseApt(result->rescheduled->programText, "out.cl");
    ASSERT_TRUE(before && after);
    ASSERT_EQ(before->path.records.size(), after->path.records.size());
    double worst = 0.0;
    const double radius = member.path.toolRadius;
    for (std::size_t i = 0; i < before->path.records.size(); ++i) {
        const auto& in = before->path.records[i];
        const auto& out = after->path.records[i];
        const Vec3 centreIn = in.tip + radius * in.axis.normalized();
        const Vec3 centreOut = out.tip + radius * out.axis.normalized();
        worst = std::max(worst, (centreOut - centreIn).norm());
    }
    EXPECT_LT(worst, 1e-3);
}

// The ball centre's speed in each feed block of a program on a combined-axes control, computed
// here from the program's own words (positions and modal F, read by a few lines of parsing that
// share nothing with the reader): the block lasts its combined move over F.
std::vector<double> centreSpeeds(const std::string& text, double radius) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    std::vector<double> speeds;
    std::array<double, 5> position{};
    double feed = 0.0;
    std::optional<Vec3> lastCentre;
    std::optional<std::array<double, 5>> last;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        bool move = false;
        for (std::string word; words >> word;) {
            const char letter = word[0];
            const double value = std::atof(word.c_str() + 1);
            const std::string_view axes = "XYZAB";
            if (const auto axis = axes.find(letter); axis != std::string_view::npos) {
                position[axis] = value;
                move = true;
            } else if (letter == 'F') {
                feed = value;
            }
        }
        if (!move) {
            continue;
        }
        const kinematics::MachineAxes axes{position[0], position[1], position[2],
                                           units::degToRad(position[3]),
                                           units::degToRad(position[4])};
        const kinematics::ToolPose pose = kinematics::forwardKinematics(machine.chain, axes);
        const Vec3 centre = pose.tip + radius * pose.axis;
        if (last && lastCentre) {
            double length = 0.0;
            for (std::size_t i = 0; i < 5; ++i) {
                length += (position[i] - (*last)[i]) * (position[i] - (*last)[i]);
            }
            const double minutes = std::sqrt(length) / feed;
            if (minutes > 0.0) {
                speeds.push_back((centre - *lastCentre).norm() / minutes);
            }
        }
        last = position;
        lastCentre = centre;
    }
    return speeds;
}

TEST(MachineLayouts, OnACombinedAxesControlEveryBlockKeepsItsCentreSpeed) {
    const fs::path machineFile =
        fs::path(BLADEAXIS_TEST_DATA_DIR) / "machines/table_a_combined_feed.json";
    const auto machine = kinematics::loadMachineFile(machineFile);
    ASSERT_TRUE(machine) << machine.error().toString();
    const auto family = blade::syntheticFamily(20261125, 4);
    ASSERT_TRUE(family);
    double worst = 0.0;
    for (blade::FamilyMember member : *family) {
        member.path.tiltB0 = 0.0;
        const auto model = blade::Blade::create(member.blade);
        const auto generated = blade::generateHelicalPath(*model, member.path);
        ASSERT_TRUE(generated) << member.name;
        JobSpec spec;
        spec.program = member.name + ".nc";
        spec.programText = gcodeText(generated->path, *machine, 3000.0, RotaryUnit::Degrees);
        spec.machineFile = machineFile;
        spec.toolRadius = member.path.toolRadius;
        const auto result = runQuietly(spec);
        ASSERT_TRUE(result) << member.name << ": " << result.error().toString();
        const std::vector<double> before = centreSpeeds(*spec.programText, *spec.toolRadius);
        const std::vector<double> after =
            centreSpeeds(result->rescheduled->programText, *spec.toolRadius);
        ASSERT_EQ(before.size(), after.size()) << member.name;
        for (std::size_t i = 0; i < before.size(); ++i) {
            if (before[i] > 1.0) { // mm/min: blocks that move the centre
                worst = std::max(worst, std::abs(after[i] / before[i] - 1.0));
            }
        }
        EXPECT_NE(result->rescheduled->programText.find(" F"), std::string::npos);
    }
    EXPECT_LT(worst, 0.01);
    std::printf("[ measure  ] largest change of a block's centre speed: %.4f %%\n", 100.0 * worst);
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

TEST(MachineLayouts, AFixedHeadRefusesTheFirstTiltWordOnlyNotEveryBlockThatRepeatsIt) {
    JobSpec spec;
    spec.program = "tilted.nc";
    std::string text = "G21 G90 G94\nG1 X0. Y0. Z5. A10. B5. F3000.\n";
    for (int i = 1; i <= 20; ++i) {
        text += "X" + std::to_string(i) + ". A" + std::to_string(10 + i) + ". B" +
                std::to_string(5 + i) + ".\n";
    }
    spec.programText = text + "M30\n";
    spec.machineFile = tableAMachineFile();
    spec.toolRadius = 4.0;
    const auto result = runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().where.line, 2);
    EXPECT_TRUE(result.error().more.empty()) << result.error().toString();
    EXPECT_NE(result.error().message.find("the first such word; later ones are not listed"),
              std::string::npos)
        << result.error().message;
}

} // namespace
} // namespace bladeaxis::job::test

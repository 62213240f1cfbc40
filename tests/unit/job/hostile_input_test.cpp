// Inputs a careless or hostile user gives: an absurd tool radius, file names that are not UTF-8.
// Each is refused with a clear message or handled, never an internal error or a partial output.

#include "core/base/file_io.h"
#include "core/kinematics/machine_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

fs::path writeCleanProgram(const fs::path& path) {
    const CleanPass& clean = cleanPass();
    std::ofstream(path, std::ios::binary)
        << aptText(clean.path, clean.toolRadius, clean.feedMmPerMin);
    return path;
}

TEST(HostileInput, AToolRadiusNoBallEndCutterHasIsRefusedAsAnInvalidArgument) {
    const fs::path folder = freshFolder("bladeaxis_hostile_radius");
    JobSpec spec;
    spec.program = writeCleanProgram(folder / "blade.cl");
    spec.outputProgram = folder / "out.cl";
    for (const double radius : {1e12, 1e308, 0.0, -4.0}) {
        spec.toolRadius = radius;
        const auto result = runQuietly(spec);
        ASSERT_FALSE(result.has_value()) << radius;
        EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument) << result.error().toString();
        EXPECT_NE(result.error().message.find("not a ball-end cutter"), std::string::npos);
        EXPECT_FALSE(fs::exists(spec.outputProgram));
    }
}

TEST(HostileInput, FileNamesThatAreNotUtf8AreReadAndNamedInTheReports) {
    const fs::path folder = freshFolder("bladeaxis_hostile_names");
    JobSpec spec;
    spec.program = writeCleanProgram(folder / "blade\xff.cl");
    spec.outputProgram = folder / "out\xfe.cl";
    spec.outputDir = folder / "report\xff";
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const auto written = writeJobOutputs(spec, *result);
    ASSERT_TRUE(written.has_value()) << written.error().toString();
    EXPECT_TRUE(fs::exists(spec.outputProgram));
    const std::string report = readTextFile(spec.outputDir / "report.json").value_or("");
    // The byte that is not UTF-8 is replaced in the JSON (U+FFFD), the rest of the name kept.
    EXPECT_NE(report.find("blade\xef\xbf\xbd.cl"), std::string::npos);
}

// A machine whose Z travel the demo fits before re-scheduling (down to -4.0 mm) but not after
// (the new orientation moves the pivot down to -6.3 mm): the job is refused before anything
// is written, naming the block, the axis and the amount.
TEST(HostileInput, AProgramReScheduledBeyondTheMachinesTravelIsRefusedAndNothingIsWritten) {
    const fs::path folder = freshFolder("bladeaxis_travel");
    JobSpec spec;
    spec.demo = true;
    spec.machineFile = fs::path(BLADEAXIS_TEST_DATA_DIR) / "machines/short_z_travel.json";
    spec.outputProgram = folder / "out.nc";
    const auto result = runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::CheckFailed) << result.error().toString();
    EXPECT_NE(result.error().message.find("Z = -6.290 mm, 0.290 mm beyond the travel"),
              std::string::npos)
        << result.error().toString();
    EXPECT_GT(result.error().where.line, 0U) << "the message names the block";
    EXPECT_FALSE(fs::exists(spec.outputProgram));
}

TEST(HostileInput, AnInputBeyondTheMachinesTravelIsReportedAsAWarning) {
    JobSpec spec;
    spec.demo = true;
    spec.reschedule = false;
    spec.machineFile = fs::path(BLADEAXIS_TEST_DATA_DIR) / "machines/short_z_travel.json";
    const auto inside = runQuietly(spec);
    ASSERT_TRUE(inside.has_value()) << inside.error().toString();
    for (const std::string& warning : inside->warnings) {
        EXPECT_EQ(warning.find("beyond the travel"), std::string::npos) << warning;
    }
    spec.machineFile.clear();
    auto machine = kinematics::defaultBladeMachine();
    ASSERT_TRUE(machine.limit(kinematics::AxisId::Y).hasTravel);
    const fs::path folder = freshFolder("bladeaxis_travel_input");
    spec.machineFile = folder / "narrow_y.json";
    std::string text =
        readTextFile(fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines/blade_ab.json")
            .value_or("");
    const std::string wide = "\"min_mm\": -330, \"max_mm\": 330";
    ASSERT_NE(text.find(wide), std::string::npos);
    text.replace(text.find(wide), wide.size(), "\"min_mm\": -1, \"max_mm\": 1");
    std::ofstream(spec.machineFile) << text;
    const auto outside = runQuietly(spec);
    ASSERT_TRUE(outside.has_value()) << outside.error().toString();
    bool warned = false;
    for (const std::string& warning : outside->warnings) {
        warned = warned || (warning.find("the input program drives Y = ") != std::string::npos &&
                            warning.find("demo_blade.nc:") == 0);
    }
    EXPECT_TRUE(warned);
}

} // namespace
} // namespace bladeaxis::job::test

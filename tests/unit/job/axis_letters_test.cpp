// What a person reads names the axes by the program's letters: on a table-B machine the rotary
// table is B and the head's tilt A, so the summary, the messages and the comparison say "B
// reversals" and "tool tilt A". Machine-readable keys stay the engine's roles, and report.json
// maps them to the letters; a table-A machine's texts and report are as they always were.

#include "core/blade/blade.h"
#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/kinematics/machine_file.h"
#include "core/report/compare_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path tableBMachineFile() {
    return fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines/table_b_head_a.json";
}

// The first member of the synthetic family: a helical pass in the engine's frame, with
// reversals for the re-scheduling to remove.
struct Member {
    toolpath::Toolpath pass;
    double toolRadius = 0.0;
};

Member familyMember() {
    const auto family = blade::syntheticFamily(20261126, 1);
    EXPECT_TRUE(family && !family->empty());
    const blade::FamilyMember& member = family->front();
    const auto model = blade::Blade::create(member.blade);
    EXPECT_TRUE(model);
    const auto generated = blade::generateHelicalPath(*model, member.path);
    EXPECT_TRUE(generated);
    return {generated ? generated->path : toolpath::Toolpath{}, member.path.toolRadius};
}

// The member posted for `machineFile` (empty: the built-in blade machine) as a re-scheduling job.
JobSpec jobOn(const Member& member, const fs::path& machineFile) {
    const auto machine = machineFile.empty()
                             ? Result<kinematics::MachineModel>(kinematics::defaultBladeMachine())
                             : kinematics::loadMachineFile(machineFile);
    EXPECT_TRUE(machine);
    JobSpec spec;
    spec.program = "member.nc";
    spec.programText = gcodeText(member.pass, *machine, 3000.0, RotaryUnit::Degrees);
    spec.machineFile = machineFile;
    spec.toolRadius = member.toolRadius;
    return spec;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(AxisLetters, ATableBMachinesSummaryNamesTheTableB) {
    const auto result = runQuietly(jobOn(familyMember(), tableBMachineFile()));
    ASSERT_TRUE(result) << result.error().toString();
    ASSERT_TRUE(result->rescheduled.has_value());
    const std::string summary = formatSummary(*result);
    for (const char* line : {"B reversals  ", "B peak vel.  ", "B peak acc.  ", "B axis       ",
                             "B peaks      ", "X peaks      ", "Y peaks      ", "Z peaks      "}) {
        EXPECT_TRUE(contains(summary, line)) << line << " in\n" << summary;
    }
    for (const char* line : {"A reversals", "A peak", "A axis"}) {
        EXPECT_FALSE(contains(summary, line)) << line << " in\n" << summary;
    }
    // The program's X comes before its Y, whichever roles they play.
    EXPECT_LT(summary.find("X peaks"), summary.find("Y peaks"));
}

TEST(AxisLetters, ATableBMachinesReportMapsTheRolesToTheProgramsLetters) {
    const auto result = runQuietly(jobOn(familyMember(), tableBMachineFile()));
    ASSERT_TRUE(result) << result.error().toString();
    const auto report = nlohmann::json::parse(reportJsonText(*result));
    const nlohmann::json expected{{"X", "Y"}, {"Y", "X"}, {"Z", "Z"}, {"A", "B"}, {"B", "A"}};
    EXPECT_EQ(report.at("axis_letters"), expected);
    EXPECT_EQ(report.at("machine_layout"), "table_b_head_a");
    EXPECT_TRUE(report.at("original").at("axes").contains("A")); // the keys stay roles
}

TEST(AxisLetters, TheDefaultMachinesTextsAndReportAreUnchanged) {
    const auto result = runQuietly(jobOn(familyMember(), {}));
    ASSERT_TRUE(result) << result.error().toString();
    ASSERT_TRUE(result->rescheduled.has_value());
    const std::string summary = formatSummary(*result);
    for (const char* line : {"A reversals  ", "A peak vel.  ", "A axis       ", "A peaks      "}) {
        EXPECT_TRUE(contains(summary, line)) << line << " in\n" << summary;
    }
    EXPECT_FALSE(contains(summary, "B reversals"));
    const auto report = nlohmann::json::parse(reportJsonText(*result));
    EXPECT_FALSE(report.contains("axis_letters"));
    EXPECT_FALSE(report.contains("machine_layout"));
}

TEST(AxisLetters, AVaryingTiltOnATableBMachineIsRefusedNamingTheHeadsA) {
    const Member member = familyMember();
    const Member tilted{withVaryingTilt(member.pass, member.toolRadius, 2.0), member.toolRadius};
    const auto result = runQuietly(jobOn(tilted, tableBMachineFile()));
    ASSERT_FALSE(result);
    const std::string& message = result.error().message;
    EXPECT_TRUE(contains(message, "the tool tilt A is")) << message;
    EXPECT_TRUE(contains(message, "fixed A head")) << message;
    EXPECT_FALSE(contains(message, "tilt B")) << message;
    EXPECT_TRUE(contains(message, "--b-tolerance-deg")) << message; // the option keeps its name
}

TEST(AxisLetters, ATableBComparisonShowsTheTableAsB) {
    JobSpec spec = jobOn(familyMember(), tableBMachineFile());
    spec.compare = true;
    spec.compareOptimum = false; // the labels, not the optimum, are under test
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result) << result.error().toString();
    ASSERT_TRUE(result->comparison.has_value());
    const report::CompareTable table = report::compareTable(*result->comparison);
    const int reversals = table.columnOf("a_reversals"); // keys stay roles
    ASSERT_GE(reversals, 0);
    EXPECT_EQ(table.columns[static_cast<std::size_t>(reversals)].header, "B reversals");
    const int peak = table.columnOf("A_peak_acceleration");
    ASSERT_GE(peak, 0);
    EXPECT_TRUE(table.columns[static_cast<std::size_t>(peak)].header.starts_with("B peak acc."));
    const std::string html = report::compareHtml(*result->comparison, "member.nc");
    EXPECT_TRUE(contains(html, "B axis against time"));
    EXPECT_FALSE(contains(html, "A axis against time"));
    EXPECT_TRUE(contains(formatSummary(*result), "B rev.  B peak acc."));
}

} // namespace
} // namespace bladeaxis::job::test

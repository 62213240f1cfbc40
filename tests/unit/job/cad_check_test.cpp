// The job's clearance check against the blade CAD (issue 6): what it refuses and what it reports.

#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/progress.h"
#include "core/base/units.h"
#include "core/cad/cad_files.h"
#include "core/job/cad_check.h"
#include "core/job/job.h"
#include "tests/unit/job/demo_job.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

cad::ClearanceReport cleanReport(std::size_t records) {
    cad::ClearanceReport report;
    report.records.assign(records, cad::RecordClearance{1.0, 2.0, 5.0});
    return report;
}

CadCheckResult checkWith(cad::ClearanceReport original, cad::ClearanceReport rescheduled) {
    CadCheckResult result;
    result.original = std::move(original);
    result.rescheduled = std::move(rescheduled);
    return result;
}

TEST(CadCheck, NewShankCollisionRefusesTheOutputUnlessForced) {
    cad::ClearanceReport after = cleanReport(10);
    after.records[4].shank = -0.3;
    after.issues.push_back({4, 57, cad::ClearanceKind::ShankCollision, 0.3});
    const CadCheckResult result = checkWith(cleanReport(10), after);
    EXPECT_EQ(introducedIssues(result).size(), 1u);
    auto refused = refuseIfColliding(result, "blade.nc", false);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::CheckFailed);
    const std::string& message = refused.error().message;
    EXPECT_NE(message.find("blade.nc:57: shank collision 0.300 mm deep"), std::string::npos)
        << message;
    EXPECT_NE(message.find("the input program does not"), std::string::npos) << message;
    EXPECT_TRUE(refuseIfColliding(result, "blade.nc", true).has_value());
}

// The ball centres are kept, so the input's gouge is in the output too: the output still
// gouges and is refused, but the message says it is the input's (the CAM's) gouge.
TEST(CadCheck, GougeKeptFromTheInputIsRefusedAndNamedAsTheInputs) {
    cad::ClearanceReport before = cleanReport(10);
    before.records[2].ball = -0.2;
    before.issues.push_back({2, 12, cad::ClearanceKind::Gouge, 0.2});
    const CadCheckResult result = checkWith(before, before);
    EXPECT_TRUE(introducedIssues(result).empty());
    auto refused = refuseIfColliding(result, "blade.nc", false);
    ASSERT_FALSE(refused.has_value());
    const std::string& message = refused.error().message;
    EXPECT_NE(message.find("blade.nc:12: gouge 0.200 mm deep"), std::string::npos) << message;
    EXPECT_NE(message.find("the input program already gouges there, 0.200 mm deep"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("1 of them as the input program already does"), std::string::npos)
        << message;
    EXPECT_TRUE(refuseIfColliding(result, "blade.nc", true).has_value());
}

// A shank that dips as deep as the input's ball already did is no longer excused.
TEST(CadCheck, ShankCollisionWhereTheInputGougesIsStillRefused) {
    cad::ClearanceReport before = cleanReport(10);
    before.records[2].ball = -0.2;
    before.issues.push_back({2, 12, cad::ClearanceKind::Gouge, 0.2});
    cad::ClearanceReport after = before;
    after.records[2].shank = -0.15;
    after.issues.push_back({2, 12, cad::ClearanceKind::ShankCollision, 0.15});
    const CadCheckResult result = checkWith(before, after);
    EXPECT_EQ(introducedIssues(result).size(), 1u);
    EXPECT_FALSE(refuseIfColliding(result, "blade.nc", false).has_value());
}

TEST(CadCheck, CleanOutputIsWritten) {
    const CadCheckResult result = checkWith(cleanReport(10), cleanReport(10));
    EXPECT_TRUE(refuseIfColliding(result, "blade.nc", false).has_value());
}

TEST(CadCheck, DemoJobChecksItsOwnBladeAndWritesItAsStep) {
    JobSpec spec = test::demoJob("bladeaxis_cad_check_job");
    auto result = test::runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->cadCheck);
    ASSERT_TRUE(result->cadCheck->rescheduled);
    EXPECT_EQ(result->cadCheck->original.records.size(), result->pass.count);
    EXPECT_TRUE(result->cadCheck->original.issues.empty());
    EXPECT_TRUE(result->cadCheck->rescheduled->issues.empty());
    // The CAD sections turn concave where the toolpath said they do (within a degree).
    const auto& sections = result->cadCheck->sections;
    ASSERT_EQ(sections.size(), result->rescheduled->schedule.basePoints.size());
    for (const SectionComparison& section : sections) {
        EXPECT_FALSE(section.engineFallback);
        EXPECT_GE(section.cadConcaveRuns, 1u) << "x = " << section.x;
        ASSERT_TRUE(section.cadExitDeg.has_value());
        EXPECT_LT(section.differenceDeg, 1.0) << "x = " << section.x;
    }
    ASSERT_TRUE(writeJobOutputs(spec, *result));
    auto step = cad::readCadFile(spec.outputDir / "demo_blade.step");
    ASSERT_TRUE(step.has_value()) << step.error().toString();
    EXPECT_EQ(step->faceCount(), 1);
    fs::remove_all(spec.outputDir);
}

TEST(CadCheck, UnreadableCadFileIsAnInputError) {
    JobSpec spec;
    spec.demo = true;
    spec.cad.file = fs::path(BLADEAXIS_TEST_DATA_DIR) / "cad/bad/truncated.step";
    auto result = test::runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().toString().find("truncated.step"), std::string::npos);
}

// Records the stages the job reports, to see how far it got.
class StageRecorder final : public ProgressSink {
  public:
    void progress(double, std::string_view stage) override { stages.emplace_back(stage); }
    void warning(std::string_view) override {}
    std::vector<std::string> stages;
};

// A taper the scheduling takes (up to 80 deg) but the check's shank model does not (below
// 60 deg) stops the job before the schedule is computed, not after.
TEST(CadCheck, TaperTheCheckCannotModelStopsTheJobBeforeScheduling) {
    JobSpec spec;
    spec.demo = true;
    spec.parameters.taperHalfAngleRad = units::degToRad(70.0);
    StageRecorder progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("--taper-deg"), std::string::npos)
        << result.error().message;
    EXPECT_EQ(std::ranges::count(progress.stages, "re-scheduling the tool orientation"), 0);
    EXPECT_EQ(std::ranges::count(progress.stages, "analysing the original axis motion"), 0);

    spec.parameters.taperHalfAngleRad = units::degToRad(59.0); // inside the model's range
    progress.stages.clear();
    spec.reschedule = false;
    EXPECT_TRUE(runJob(spec, progress, cancel).has_value());
}

// A box a metre away from the demo's toolpath is not its blade: every clearance would be capped
// at the search limit and the check would pass silently.
TEST(CadCheck, CadFarFromTheToolpathIsAGeometryErrorNamingTheFile) {
    JobSpec spec;
    spec.demo = true;
    spec.cad.file = fs::path(BLADEAXIS_TEST_DATA_DIR) / "cad/box_solid_inch.step";
    spec.cad.placement.translation = Vec3(1000.0, 0.0, 0.0);
    auto result = test::runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Geometry);
    const std::string text = result.error().toString();
    EXPECT_NE(text.find("box_solid_inch.step"), std::string::npos) << text;
    EXPECT_NE(text.find("does not fit the program"), std::string::npos) << text;
    EXPECT_NE(text.find("CL points are farther than the 5 mm search limit"), std::string::npos)
        << text;
}

// The demo blade shifted along the rotary axis leaves part of the program without blade.
TEST(CadCheck, CadNotSpanningTheProgramIsAGeometryError) {
    JobSpec demo = test::demoJob("bladeaxis_cad_check_span");
    auto written = test::runQuietly(demo);
    ASSERT_TRUE(written.has_value()) << written.error().toString();
    ASSERT_TRUE(writeJobOutputs(demo, *written));
    JobSpec spec;
    spec.demo = true;
    spec.cad.file = demo.outputDir / "demo_blade.step";
    spec.cad.placement.translation = Vec3(12.0, 0.0, 0.0);
    auto result = test::runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Geometry);
    EXPECT_NE(result.error().toString().find("found the CAD at x 12.0 .. 32.0,"), std::string::npos)
        << result.error().toString();
    spec.cad.placement.translation = Vec3::Zero(); // in place it fits
    EXPECT_TRUE(test::runQuietly(spec).has_value());
    fs::remove_all(demo.outputDir);
}

// On a table-B machine the blade lies along the program's Y: the demo writes its blade there,
// and a CAD file read with the program is turned into the engine's frame, so the blade the demo
// wrote fits its program again (turned wrongly, it would lie across the path, 20 mm away).
TEST(CadCheck, ATableBMachinesBladeIsWrittenAndReadInTheProgramsFrame) {
    const fs::path machine =
        fs::path(BLADEAXIS_SOURCE_DIR) / "resources/machines/table_b_head_a.json";
    JobSpec demo = test::demoJob("bladeaxis_cad_check_table_b");
    demo.machineFile = machine;
    auto written = test::runQuietly(demo);
    ASSERT_TRUE(written.has_value()) << written.error().toString();
    ASSERT_TRUE(writeJobOutputs(demo, *written));
    auto step = cad::readCadFile(demo.outputDir / "demo_blade.step");
    ASSERT_TRUE(step.has_value()) << step.error().toString();
    const cad::BoundingBox box = step->bounds();
    EXPECT_GT(box.max.y() - box.min.y(), 19.0); // the 20 mm span along Y
    JobSpec spec;
    spec.demo = true;
    spec.machineFile = machine;
    spec.cad.file = demo.outputDir / "demo_blade.step";
    auto result = test::runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->cadCheck && result->cadCheck->rescheduled);
    EXPECT_TRUE(result->cadCheck->original.issues.empty());
    EXPECT_TRUE(result->cadCheck->rescheduled->issues.empty());
    fs::remove_all(demo.outputDir);
}

// The clearance per layer reaches report.json (each layer's minima over its CL points), each
// CL point's clearance layers.csv, and a one-line summary the batch output.
TEST(CadCheck, DemoOutputsCarryTheClearancePerLayerAndPerPoint) {
    JobSpec spec = test::demoJob("bladeaxis_cad_check_layers");
    auto result = test::runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(writeJobOutputs(spec, *result));
    const cad::ClearanceReport& after = *result->cadCheck->rescheduled;
    const auto report = nlohmann::json::parse(*readTextFile(spec.outputDir / "report.json"));
    const auto& layers = report.at("clearance").at("rescheduled").at("layers");
    ASSERT_EQ(layers.size(), result->rescheduled->schedule.layers.size());
    for (const auto& layer : layers) {
        const std::size_t first = layer.at("first_record");
        const std::size_t last = layer.at("last_record");
        double shank = 1e300;
        for (std::size_t i = first; i <= last; ++i) {
            shank = std::min(shank, after.records[i].shank);
        }
        EXPECT_EQ(layer.at("min_shank_mm").get<double>(), shank);
        EXPECT_EQ(layer.at("first_line").get<int>(),
                  result->program.path().records[result->pass.first + first].line);
    }
    const std::string csv = *readTextFile(spec.outputDir / "layers.csv");
    EXPECT_NE(csv.find("ddtheta_deg_mm2,ball_clearance_mm,shank_clearance_mm\n"),
              std::string::npos);
    const std::string secondRow =
        csv.substr(csv.find('\n') + 1, csv.find('\n', csv.find('\n') + 1) - csv.find('\n') - 1);
    EXPECT_EQ(secondRow.substr(secondRow.rfind(',') + 1), formatShortest(after.records[0].shank));
    EXPECT_NE(formatSummary(*result).find("clearance    ball >= "), std::string::npos);
    fs::remove_all(spec.outputDir);
}

} // namespace
} // namespace bladeaxis::job

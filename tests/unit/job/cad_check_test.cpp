// The job's clearance check against the blade CAD (issue 6): what it refuses and what it reports.

#include "core/base/file_io.h"
#include "core/cad/cad_files.h"
#include "core/job/cad_check.h"
#include "core/job/job.h"

#include <gtest/gtest.h>

#include <filesystem>

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
    EXPECT_NE(refused.error().message.find("blade.nc:57"), std::string::npos)
        << refused.error().message;
    EXPECT_TRUE(refuseIfColliding(result, "blade.nc", true).has_value());
}

TEST(CadCheck, GougesOfTheInputsOwnCentresAreNotBlamedOnTheSchedule) {
    cad::ClearanceReport before = cleanReport(10);
    before.records[2].ball = -0.2;
    before.issues.push_back({2, 12, cad::ClearanceKind::Gouge, 0.2});
    cad::ClearanceReport after = before;
    // At the channel limit the shank may go as deep as the ball already is, not deeper.
    after.records[2].shank = -0.205;
    after.issues.push_back({2, 12, cad::ClearanceKind::ShankCollision, 0.205});
    const CadCheckResult result = checkWith(before, after);
    EXPECT_TRUE(introducedIssues(result).empty());
    EXPECT_TRUE(refuseIfColliding(result, "blade.nc", false).has_value());
}

TEST(CadCheck, DemoJobChecksItsOwnBladeAndWritesItAsStep) {
    JobSpec spec;
    spec.demo = true;
    spec.outputDir = fs::temp_directory_path() / "bladeaxis_cad_check_job";
    fs::remove_all(spec.outputDir);
    NullProgressSink progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->cadCheck);
    ASSERT_TRUE(result->cadCheck->rescheduled);
    EXPECT_EQ(result->cadCheck->original.records.size(), result->pass.count);
    EXPECT_TRUE(introducedIssues(*result->cadCheck).empty());
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
    NullProgressSink progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().toString().find("truncated.step"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::job

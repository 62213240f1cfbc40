// `--compare` through the job API: the comparison is computed on the job's own cutting pass and
// written as compare.json, compare.csv and a self-contained report.html.

#include "core/base/file_io.h"
#include "core/job/job.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

TEST(CompareJob, DemoComparisonWritesJsonCsvAndHtml) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = true;
    spec.outputDir = fs::temp_directory_path() / "bladeaxis_compare_job";
    fs::remove_all(spec.outputDir);
    NullProgressSink progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->comparison);
    ASSERT_TRUE(writeJobOutputs(spec, *result));

    const std::size_t methods = result->comparison->methods.size();
    EXPECT_GE(methods, 3u);
    const auto json = nlohmann::json::parse(*readTextFile(spec.outputDir / "compare.json"));
    EXPECT_EQ(json["methods"].size(), methods);
    EXPECT_EQ(json["methods"][0]["method"], "original");

    const std::string csv = *readTextFile(spec.outputDir / "compare.csv");
    EXPECT_EQ(count(csv, "\n"), methods + 1);

    const std::string html = *readTextFile(spec.outputDir / "report.html");
    EXPECT_EQ(count(html, "<figure>"), 7u); // A position, velocity, acceleration; S-theta; X Y Z
    EXPECT_NE(html.find("stheta-best"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    fs::remove_all(spec.outputDir);
}

TEST(CompareJob, TheEnginesRowMatchesTheRescheduledProgram) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = true;
    NullProgressSink progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const compare::MethodResult* best = result->comparison->find("stheta-best");
    ASSERT_NE(best, nullptr);
    // The same engine, parameters and evaluation: the comparison row is the job's own result.
    EXPECT_NEAR(best->t1.time, result->rescheduled->constantFeed.time,
                1e-6 * result->rescheduled->constantFeed.time);
    EXPECT_EQ(best->profile.aReversals.count, result->rescheduled->profile.aReversals.count);
}

} // namespace
} // namespace bladeaxis::job

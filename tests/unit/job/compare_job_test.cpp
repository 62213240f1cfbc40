// `--compare` through the job API: the comparison is computed on the job's own cutting pass and
// written as compare.json, compare.csv and a self-contained report.html.

#include "core/base/file_io.h"
#include "core/job/job.h"
#include "core/report/compare_report.h"
#include "core/report/markup.h"
#include "tests/unit/job/demo_job.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
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
    JobSpec spec = test::demoJob("bladeaxis_compare_job", true);
    auto result = test::runQuietly(spec);
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
    const report::CompareTable table = report::compareTable(*result->comparison);
    // The derived figures report.html shows are in the CSV too, every axis against both.
    for (const char* key :
         {"X_velocity_reduction_vs_best_quaternion_setting", "Z_acceleration_reduction_vs_original",
          "t2_gain_vs_original", "peak_theta_dd_ratio_to_optimal_lp"}) {
        EXPECT_NE(csv.find(key), std::string::npos) << key;
    }

    const std::string html = *readTextFile(spec.outputDir / "report.html");
    // Every column of the GUI's table (one definition), headers escaped as the page prints them.
    for (const report::CompareTableColumn& column : table.columns) {
        EXPECT_NE(html.find("<th>" + report::escapeMarkup(column.header) + "</th>"),
                  std::string::npos)
            << column.key;
    }
    const auto layers = report::plottedLayers(*result->comparison);
    const std::size_t total = result->comparison->reference.layers.size();
    EXPECT_GE(layers.size(), std::min<std::size_t>(total, 3));
    // A position, velocity, acceleration; one S-theta plane per plotted layer; X, Y, Z velocity.
    EXPECT_EQ(count(html, "<figure>"), 6 + layers.size());
    for (std::size_t layer : layers) {
        EXPECT_EQ(count(html, "Layer " + std::to_string(layer + 1) + " in the S-theta plane"), 1u)
            << layer;
    }
    EXPECT_NE(std::find(layers.begin(), layers.end(), total - 1), layers.end())
        << "the last cutting layer is shown";
    EXPECT_NE(html.find("stheta-best"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("Not computed"), std::string::npos);
    fs::remove_all(spec.outputDir);
}

// Issue 4: a figure the comparison could not compute is named with its reason in every output,
// not left out silently.
TEST(CompareJob, MissingFiguresAreReportedEverywhere) {
    JobSpec spec = test::demoJob("bladeaxis_compare_job_missing", true);
    auto result = test::runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    auto& comparison = *result->comparison;
    comparison.optimumFailures = {"optimal-lp: layer 2: no convergence"};
    comparison.methods.front().t2.reset();
    comparison.methods.front().t2Failure = "the axis limits stop the tool";
    ASSERT_TRUE(writeJobOutputs(spec, *result));

    const auto json = nlohmann::json::parse(*readTextFile(spec.outputDir / "compare.json"));
    EXPECT_EQ(json["optimum_failures"][0], "optimal-lp: layer 2: no convergence");
    EXPECT_EQ(json["methods"][0]["t2_failure"], "the axis limits stop the tool");
    const std::string html = *readTextFile(spec.outputDir / "report.html");
    EXPECT_NE(html.find("optimal-lp: layer 2: no convergence"), std::string::npos);
    EXPECT_NE(html.find("original: T2: the axis limits stop the tool"), std::string::npos);
    const std::string summary = formatSummary(*result);
    EXPECT_NE(summary.find("not computed optimal-lp: layer 2"), std::string::npos) << summary;
    fs::remove_all(spec.outputDir);
}

TEST(CompareJob, TheEnginesRowMatchesTheRescheduledProgram) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = true;
    auto result = test::runQuietly(spec);
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

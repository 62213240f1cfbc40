// What the GUI and --batch export besides the program: the re-scheduled toolpath as CL data, and
// the per-layer motion figures the layer list shows.
#include "app/batch/batch_runner.h"
#include "core/base/file_io.h"
#include "core/io/program.h"
#include "core/job/job.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

const JobResult& demoResult() {
    static const JobResult result = [] {
        JobSpec spec;
        spec.demo = true;
        NullProgressSink progress;
        CancelToken cancel;
        return *runJob(spec, progress, cancel);
    }();
    return result;
}

TEST(ClExport, ReReadClDataHasTheRescheduledTipsAndAxes) {
    const JobResult& result = demoResult();
    const auto text = rescheduledClText(result);
    ASSERT_TRUE(text.has_value()) << text.error().toString();
    const auto reread = io::parseProgram(*text, "demo.cl", io::ProgramFormat::Apt, result.machine);
    ASSERT_TRUE(reread.has_value()) << reread.error().toString();
    const auto& records = reread->path().records;
    ASSERT_EQ(records.size(), result.program.path().records.size());
    ASSERT_TRUE(reread->path().toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*reread->path().toolRadius, *result.toolRadius);
    const auto pass = rescheduledRecords(
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count),
        *result.rescheduled);
    for (std::size_t i = 0; i < pass.size(); ++i) {
        const auto& read = records[result.pass.first + i];
        ASSERT_LT((read.tip - pass[i].tip).norm(), 2e-6) << "record " << i;
        ASSERT_LT((read.axis - pass[i].axis).norm(), 2e-6) << "record " << i;
    }
}

TEST(ClExport, BatchWritesTheClFileBesideTheProgram) {
    const fs::path folder = fs::temp_directory_path() / "bladeaxis_cl_export";
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ostringstream out, err;
    const int code = app::runBatchCommandLine(
        {"bladeaxis", "--batch", "--demo", "--quiet", "--cl-output", (folder / "demo.cl").string()},
        out, err);
    ASSERT_EQ(code, 0) << err.str();
    const auto written = readTextFile(folder / "demo.cl");
    ASSERT_TRUE(written.has_value());
    EXPECT_EQ(*written, *rescheduledClText(demoResult()));
}

TEST(ClExport, AnalyseOnlyJobHasNoClData) {
    JobResult result; // no rescheduled outcome
    const auto text = rescheduledClText(result);
    ASSERT_FALSE(text.has_value());
    EXPECT_EQ(text.error().code, ErrorCode::InvalidArgument);
}

TEST(LayerMotion, MatchesTheLayersOfReportJson) {
    const JobResult& result = demoResult();
    const auto motion = layerMotionOf(result);
    const auto report = nlohmann::json::parse(reportJsonText(result));
    const auto& layers = report.at("rescheduled").at("layers");
    ASSERT_EQ(motion.size(), layers.size());
    bool anyReversalBefore = false;
    for (std::size_t k = 0; k < motion.size(); ++k) {
        EXPECT_EQ(motion[k].reversalsBefore, layers[k].at("a_reversals_before").get<int>());
        EXPECT_EQ(motion[k].reversalsAfter, 0);
        EXPECT_NEAR(motion[k].peakAccelerationAfter * 180.0 / 3.141592653589793,
                    layers[k].at("peak_a_acceleration_deg_s2_after").get<double>(), 1e-9);
        anyReversalBefore = anyReversalBefore || motion[k].reversalsBefore > 0;
    }
    EXPECT_TRUE(anyReversalBefore); // the demo's original program reverses
}

// Per-layer linear-axis peaks lie within the program's overall peaks, and the largest layer
// peak is the overall one whenever the overall peak falls inside the cutting pass.
TEST(LayerMotion, LinearAxisPeaksPerLayerStayWithinTheProgramPeaks) {
    const auto report = nlohmann::json::parse(reportJsonText(demoResult()));
    const auto& layers = report.at("rescheduled").at("layers");
    for (const char* axis : {"X", "Y", "Z"}) {
        const std::string key = std::string("peak_") + static_cast<char>(std::tolower(axis[0]));
        for (const char* when : {"before", "after"}) {
            const auto& overall = std::string(when) == "before"
                                      ? report.at("original").at("axes")
                                      : report.at("rescheduled").at("analysis").at("axes");
            const double programPeak = overall.at(axis).at("peak_velocity_mm_s").get<double>();
            double layerPeak = 0.0;
            for (const auto& layer : layers) {
                layerPeak =
                    std::max(layerPeak, layer.at(key + "_velocity_mm_s_" + when).get<double>());
            }
            EXPECT_GT(layerPeak, 0.0) << axis << ' ' << when;
            EXPECT_LE(layerPeak, programPeak + 1e-9) << axis << ' ' << when;
        }
    }
}

} // namespace
} // namespace bladeaxis::job

namespace bladeaxis::job {
namespace {

TEST(CompareJob, WithoutTheOptimumLeavesOutTheOptimalMethods) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = true;
    spec.compareOptimum = false;
    NullProgressSink progress;
    CancelToken cancel;
    const auto result = runJob(spec, progress, cancel);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->comparison.has_value());
    EXPECT_EQ(result->comparison->find("optimal-qp"), nullptr);
    EXPECT_EQ(result->comparison->find("optimal-lp"), nullptr);
    EXPECT_NE(result->comparison->find("stheta-best"), nullptr);
    EXPECT_NE(result->comparison->find("quaternion"), nullptr);
}

TEST(BatchCli, NoOptimumIsAcceptedWithCompare) {
    std::ostringstream out, err;
    const int code = app::runBatchCommandLine(
        {"bladeaxis", "--batch", "--demo", "--quiet", "--compare", "--no-optimum"}, out, err);
    EXPECT_EQ(code, 0) << err.str();
}

} // namespace
} // namespace bladeaxis::job

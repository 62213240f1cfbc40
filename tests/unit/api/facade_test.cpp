// The facade plug-ins and the Python module use: the same results as the job API the window and
// the command line call, S-theta curves inside their channel, errors as values with the
// command line's exit codes, progress and cancel.
#include "core/api/bladeaxis.h"
#include "core/base/file_io.h"
#include "core/job/job.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace bladeaxis::api {
namespace {

constexpr const char* kDemoJob = R"({"schema": "bladeaxis-job/1", "demo": true})";

std::filesystem::path scratchFolder(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / ("bladeaxis_api_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// report.json without what differs between two runs of the same job: wall times, at any depth.
void eraseTimings(nlohmann::json& json) {
    if (json.is_object()) {
        json.erase("timing");
    }
    if (json.is_structured()) {
        for (auto& child : json) {
            eraseTimings(child);
        }
    }
}

nlohmann::json withoutTimings(const std::string& text) {
    auto json = nlohmann::json::parse(text);
    eraseTimings(json);
    return json;
}

TEST(Facade, GivesTheSameReportAsTheJobApi) {
    const auto outcome = runJobJson(kDemoJob, scratchFolder("same"));
    ASSERT_TRUE(outcome) << outcome.error().toString();

    job::JobSpec spec;
    spec.demo = true;
    NullProgressSink sink;
    const auto direct = job::runJob(spec, sink, CancelToken{});
    ASSERT_TRUE(direct);
    EXPECT_EQ(withoutTimings(outcome->reportJson()),
              withoutTimings(job::reportJsonText(*direct, &spec)));
    EXPECT_EQ(*outcome->programText(), direct->rescheduled->programText);
}

TEST(Facade, LayerCurvesTurnOneWayInsideTheirChannel) {
    const auto outcome = runJobJson(kDemoJob, scratchFolder("layers"));
    ASSERT_TRUE(outcome);
    const auto layers = outcome->layers();
    ASSERT_GT(layers.size(), 3u);
    for (const LayerCurve& layer : layers) {
        ASSERT_EQ(layer.s.size(), layer.thetaRescheduled.size());
        ASSERT_EQ(layer.s.size(), layer.thetaOriginal.size());
        ASSERT_EQ(layer.s.size(), layer.thetaMin.size());
        ASSERT_GT(layer.s.size(), 2u);
        EXPECT_FALSE(layer.keptOriginal);
        const double direction = layer.thetaRescheduled.back() - layer.thetaRescheduled.front();
        for (std::size_t k = 0; k < layer.s.size(); ++k) {
            EXPECT_GE(layer.thetaRescheduled[k], layer.thetaMin[k] - 1e-9);
            EXPECT_LE(layer.thetaRescheduled[k], layer.thetaMax[k] + 1e-9);
            if (k > 0) {
                EXPECT_GT(layer.s[k], layer.s[k - 1]);
                EXPECT_GE((layer.thetaRescheduled[k] - layer.thetaRescheduled[k - 1]) * direction,
                          -1e-12);
            }
        }
    }
}

TEST(Facade, ReportsProgressAndWritesTheProgram) {
    const auto folder = scratchFolder("write");
    int calls = 0;
    double last = -1.0;
    Callbacks callbacks;
    callbacks.progress = [&](double fraction, std::string_view) {
        ++calls;
        EXPECT_GE(fraction, last);
        last = fraction;
    };
    const auto outcome = runJobJson(kDemoJob, folder, callbacks);
    ASSERT_TRUE(outcome);
    EXPECT_GT(calls, 2);
    ASSERT_TRUE(outcome->writeProgram(folder / "out.nc"));
    EXPECT_EQ(readTextFile(folder / "out.nc").value_or(""), *outcome->programText());
}

TEST(Facade, WritesTheOutputsTheJobNamesInsideItsFolder) {
    const auto folder = scratchFolder("outputs");
    const auto outcome = runJobJson(
        R"({"schema": "bladeaxis-job/1", "demo": true, "output_program": "new.nc",
            "output_dir": "report"})",
        folder);
    ASSERT_TRUE(outcome) << outcome.error().toString();
    ASSERT_TRUE(outcome->writeOutputs());
    EXPECT_TRUE(std::filesystem::exists(folder / "new.nc"));
    EXPECT_TRUE(std::filesystem::exists(folder / "report" / "report.json"));
}

TEST(Facade, ErrorsAreValuesWithTheCommandLinesExitCodes) {
    const auto folder = scratchFolder("errors");
    const auto missing =
        runJobJson(R"({"schema": "bladeaxis-job/1", "program": "absent.nc"})", folder);
    ASSERT_FALSE(missing);
    EXPECT_EQ(exitCodeFor(missing.error()), 3);
    EXPECT_NE(missing.error().toString().find("absent.nc"), std::string::npos);

    const auto malformed =
        runJobJson(R"({"schema": "bladeaxis-job/1", "tool_radius_mm": -2})", folder);
    ASSERT_FALSE(malformed);
    EXPECT_EQ(exitCodeFor(malformed.error()), 2);

    const auto missingFile = runJobFile(folder / "no_such_job.json");
    ASSERT_FALSE(missingFile);
    EXPECT_EQ(exitCodeFor(missingFile.error()), 3);
}

TEST(Facade, ACancelledJobEndsWithExitCodeSeven) {
    CancelToken cancel;
    cancel.requestCancel();
    Callbacks callbacks;
    callbacks.cancel = &cancel;
    const auto outcome = runJobJson(kDemoJob, scratchFolder("cancel"), callbacks);
    ASSERT_FALSE(outcome);
    EXPECT_EQ(outcome.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(exitCodeFor(outcome.error()), 7);
}

TEST(Facade, AnAnalysisHasNoProgram) {
    const auto outcome =
        runJobJson(R"({"schema": "bladeaxis-job/1", "demo": true, "analyse_only": true})",
                   scratchFolder("analyse"));
    ASSERT_TRUE(outcome) << outcome.error().toString();
    EXPECT_FALSE(outcome->rescheduled());
    EXPECT_FALSE(outcome->programText());
    EXPECT_TRUE(outcome->layers().empty());
}

} // namespace
} // namespace bladeaxis::api

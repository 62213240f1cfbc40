#include "core/base/file_io.h"
#include "core/job/demo_program.h"
#include "core/job/job.h"

#include <gtest/gtest.h>

#include <clocale>
#include <filesystem>
#include <limits>
#include <regex>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

Result<JobResult> runDemo() {
    JobSpec spec;
    spec.demo = true;
    NullProgressSink progress;
    CancelToken cancel;
    return runJob(spec, progress, cancel);
}

TEST(DemoJob, OriginalProgramReversesTheAAxis) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_GT(result->original.aReversals.count, 0);
    EXPECT_GT(result->original.aReversals.backwardTravel, 0.0);
    EXPECT_GT(result->pass.count, 1000u);
}

TEST(DemoJob, ATurnsAboutOnceAroundPerRevolution) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value());
    const std::vector<double> a = result->original.positions(kinematics::AxisId::A);
    const double turns = std::abs(a.back() - a.front()) / (2.0 * 3.141592653589793);
    EXPECT_GT(turns, 3.0);
}

// The demo's outputs include the generated program (demo_blade.nc), so a demo job keeps the
// input text that other jobs release once the program is rewritten.
TEST(DemoJob, KeepsTheGeneratedProgramText) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->rescheduled);
    EXPECT_NE(result->programText().find("G1"), std::string::npos);
}

TEST(DemoJob, IsDeterministic) {
    auto first = runDemo();
    auto second = runDemo();
    ASSERT_TRUE(first && second);
    EXPECT_EQ(first->programText(), second->programText());
    // Everything but the measured wall times is bit-identical.
    auto withoutTimings = [](const JobResult& result) {
        std::string text = reportJsonText(result);
        static const std::regex timing(R"re("(timing|seconds|job_s)": (\{[^}]*\}|[-0-9.e]+))re");
        return std::regex_replace(text, timing, "");
    };
    EXPECT_EQ(withoutTimings(*first), withoutTimings(*second));
    ASSERT_TRUE(first->rescheduled && second->rescheduled);
    EXPECT_EQ(first->rescheduled->programText, second->rescheduled->programText);
}

TEST(Job, CancelledJobStopsWithCancelled) {
    JobSpec spec;
    spec.demo = true;
    NullProgressSink progress;
    CancelToken cancel;
    cancel.requestCancel();
    auto result = runJob(spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

// What a job reports as it goes, with its share of the whole.
class ProgressRecorder final : public ProgressSink {
  public:
    void progress(double fraction, std::string_view stage) override {
        steps.emplace_back(fraction, stage);
    }
    void warning(std::string_view) override {}
    std::vector<std::pair<double, std::string>> steps;
};

// The re-scheduling, the longest part of a large job (about 3 s at five million blocks), shows
// each of its stages in order, and the job's progress never goes back.
TEST(Job, TheReschedulingReportsEachOfItsStagesInOrder) {
    JobSpec spec;
    spec.demo = true;
    ProgressRecorder progress;
    CancelToken cancel;
    ASSERT_TRUE(runJob(spec, progress, cancel).has_value());
    std::vector<std::string> stages;
    for (std::size_t i = 0; i < progress.steps.size(); ++i) {
        stages.push_back(progress.steps[i].second);
        if (i > 0) {
            EXPECT_GE(progress.steps[i].first, progress.steps[i - 1].first) << stages.back();
        }
    }
    const std::vector<std::string> rescheduling{
        "re-scheduling the tool orientation", "computing the new machine axes",
        "writing the re-scheduled program", "reading the written program back to check it",
        "analysing the new axis motion"};
    const auto first = std::ranges::find(stages, rescheduling.front());
    ASSERT_NE(first, stages.end());
    ASSERT_GE(static_cast<std::size_t>(stages.end() - first), rescheduling.size());
    EXPECT_EQ(
        std::vector<std::string>(first, first + static_cast<std::ptrdiff_t>(rescheduling.size())),
        rescheduling);
}

// A program of some thousand lines (the demo with comment lines after its first) shows its read
// moving through the reading's share of the progress, not one step for the whole read.
TEST(Job, ALongReadShowsHowFarItHasCome) {
    const auto demo = demoProgram(kinematics::defaultBladeMachine());
    ASSERT_TRUE(demo.has_value()) << demo.error().toString();
    std::string padded = demo->text;
    const std::size_t firstLineEnd = padded.find('\n') + 1;
    std::string comments;
    for (int i = 0; i < 3 * 4096; ++i) {
        comments += "(PADDING)\n";
    }
    padded.insert(firstLineEnd, comments);
    JobSpec spec;
    spec.program = "padded.nc";
    spec.programText = padded;
    spec.toolRadius = demo->toolRadius;
    spec.reschedule = false;
    ProgressRecorder progress;
    CancelToken cancel;
    ASSERT_TRUE(runJob(spec, progress, cancel).has_value());
    std::vector<double> reading;
    for (const auto& [fraction, stage] : progress.steps) {
        if (stage == "reading the program") {
            reading.push_back(fraction);
        }
    }
    ASSERT_GE(reading.size(), 3u);
    EXPECT_EQ(reading.front(), 0.05);
    for (std::size_t i = 1; i < reading.size(); ++i) {
        EXPECT_GT(reading[i], reading[i - 1]);
        EXPECT_LE(reading[i], 0.3);
    }
}

TEST(Job, MissingProgramIsFileNotFound) {
    JobSpec spec;
    spec.program = "/nonexistent/blade.nc";
    NullProgressSink progress;
    CancelToken cancel;
    auto result = runJob(spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::FileNotFound);
}

TEST(Job, GeneratedAptProgramAnalysesLikeItsGcodeTwin) {
    const auto machine = kinematics::defaultBladeMachine();
    GenerateRequest request;
    request.revolutions = 2.0;
    auto gcode = generateProgram(request, machine);
    request.format = "apt";
    auto apt = generateProgram(request, machine);
    ASSERT_TRUE(gcode && apt);
    const fs::path dir = fs::temp_directory_path() / "bladeaxis_job_twin";
    fs::create_directories(dir);
    ASSERT_TRUE(writeFileAtomically(dir / "twin.nc", gcode->text));
    ASSERT_TRUE(writeFileAtomically(dir / "twin.cls", apt->text));
    NullProgressSink progress;
    CancelToken cancel;
    JobSpec spec;
    spec.program = dir / "twin.nc";
    spec.toolRadius = gcode->toolRadius; // G-code does not state the ball radius
    auto fromGcode = runJob(spec, progress, cancel);
    spec.program = dir / "twin.cls";
    spec.toolRadius.reset(); // the CL file states it (CUTTER)
    auto fromApt = runJob(spec, progress, cancel);
    fs::remove_all(dir);
    ASSERT_TRUE(fromGcode.has_value()) << fromGcode.error().toString();
    ASSERT_TRUE(fromApt.has_value()) << fromApt.error().toString();
    EXPECT_EQ(fromGcode->original.aReversals.count, fromApt->original.aReversals.count);
    EXPECT_NEAR(fromGcode->original.pathLength, fromApt->original.pathLength,
                1e-3 * fromGcode->original.pathLength);
    ASSERT_TRUE(fromGcode->rescheduled && fromApt->rescheduled);
    EXPECT_EQ(fromGcode->rescheduled->profile.aReversals.count,
              fromApt->rescheduled->profile.aReversals.count);
    EXPECT_NEAR(fromGcode->rescheduled->constantFeed.time, fromApt->rescheduled->constantFeed.time,
                1e-2 * fromGcode->rescheduled->constantFeed.time);
}

TEST(DemoJob, OutputsDoNotDependOnADecimalCommaLocale) {
    auto reference = runDemo();
    ASSERT_TRUE(reference.has_value());
    const std::string inC = reportJsonText(*reference);
    const std::string saved = std::setlocale(LC_ALL, nullptr);
    if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr) {
        GTEST_SKIP() << "de_DE.UTF-8 not installed";
    }
    auto localised = runDemo();
    std::setlocale(LC_ALL, saved.c_str());
    ASSERT_TRUE(localised.has_value());
    EXPECT_EQ(localised->programText(), reference->programText());
    // Only the timing differs between two runs; compare everything before it.
    const std::string inGerman = reportJsonText(*localised);
    EXPECT_EQ(inGerman.substr(0, inGerman.find("\"timing\"")),
              inC.substr(0, inC.find("\"timing\"")));
}

} // namespace
} // namespace bladeaxis::job

namespace bladeaxis::job {
namespace {

TEST(Job, OriginalReadyHookSeesTheProgramBeforeTheReschedule) {
    JobSpec spec;
    spec.demo = true;
    NullProgressSink progress;
    CancelToken cancel;
    int calls = 0;
    std::size_t records = 0;
    bool rescheduledYet = true;
    const auto result = runJob(spec, progress, cancel, [&](const JobResult& partial) {
        ++calls;
        records = partial.pass.count;
        rescheduledYet = partial.rescheduled.has_value();
    });
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_EQ(calls, 1);
    EXPECT_FALSE(rescheduledYet);
    EXPECT_EQ(records, result->pass.count);
    EXPECT_GT(records, 0u);
}

TEST(JobSummary, SaysHigherWhenAFigureRoseAndNeverPrintsANegativeReduction) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value() && result->rescheduled);
    auto& before = result->original.axes[static_cast<int>(kinematics::AxisId::A)];
    const auto& after = result->rescheduled->profile.axis(kinematics::AxisId::A);
    before.peakVelocity = after.peakVelocity / 10.0;
    const std::string summary = formatSummary(*result);
    EXPECT_NE(summary.find("deg/s (900.0% higher)"), std::string::npos) << summary;
    EXPECT_FALSE(std::regex_search(summary, std::regex(R"(-[0-9.]+%)"))) << summary;
}

TEST(JobSummary, AnInputFigureOfAboutZeroGetsNoPercentage) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value() && result->rescheduled);
    result->original.axes[static_cast<int>(kinematics::AxisId::A)].peakVelocity = 1e-12;
    const std::string summary = formatSummary(*result);
    EXPECT_NE(summary.find("(the input's is about 0)"), std::string::npos) << summary;
}

TEST(JobSummary, NoLayerReScheduledSaysSoInsteadOfAnInfiniteClearance) {
    auto result = runDemo();
    ASSERT_TRUE(result.has_value() && result->rescheduled);
    result->rescheduled->minChannelClearanceRad = std::numeric_limits<double>::infinity();
    const std::string summary = formatSummary(*result);
    EXPECT_EQ(summary.find("inf"), std::string::npos) << summary;
    EXPECT_NE(summary.find("channel clearance not applicable"), std::string::npos) << summary;
}

} // namespace
} // namespace bladeaxis::job

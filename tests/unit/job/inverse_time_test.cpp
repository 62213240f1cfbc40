// A program in inverse time (G93) is timed by its blocks: F is 1 / the block's time, whatever
// the block's length. Re-scheduling keeps the ball centres and writes the same F, so every block
// keeps its time and the ball centre (and with it the contact point of a ball-end cutter, which
// is the centre plus R times the surface normal) keeps its speed, while the tip, whose chords
// change, runs at new speeds. The analysis must describe the program as written.

#include "core/base/file_io.h"
#include "core/io/program.h"
#include "core/kinematics/machine_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

struct InverseTimeJob {
    fs::path input, output;
    Result<JobResult> result = makeError(ErrorCode::Internal, "not run");
};

const InverseTimeJob& inverseTimeJob() {
    static const InverseTimeJob job = [] {
        InverseTimeJob run;
        // One folder per process: ctest runs the two tests of this file in parallel.
        const fs::path folder =
            fs::temp_directory_path() / ("bladeaxis_inverse_time_" + std::to_string(::getpid()));
        fs::remove_all(folder);
        fs::create_directories(folder);
        const CleanPass& clean = cleanPass();
        run.input = folder / "blade_g93.nc";
        run.output = folder / "blade_g93_rescheduled.nc";
        std::ofstream(run.input, std::ios::binary)
            << gcodeText(clean.path, kinematics::defaultBladeMachine(), clean.feedMmPerMin,
                         RotaryUnit::Degrees, 0.0, FeedMode::InverseTime);
        JobSpec spec;
        spec.program = run.input;
        spec.toolRadius = clean.toolRadius;
        spec.outputProgram = run.output;
        run.result = runQuietly(spec);
        if (run.result) {
            (void)writeJobOutputs(spec, *run.result);
        }
        return run;
    }();
    return job;
}

std::vector<toolpath::ClRecord> recordsOf(const fs::path& path) {
    auto text = readTextFile(path);
    EXPECT_TRUE(text.has_value());
    auto program = io::readProgramText(text.value_or(""), path, kinematics::defaultBladeMachine());
    EXPECT_TRUE(program.has_value()) << program.error().toString();
    return program ? program->path().records : std::vector<toolpath::ClRecord>{};
}

// Seconds of every feed block after the first (the reader's tip feed is the tip chord over the
// block's time).
std::vector<double> blockTimes(const std::vector<toolpath::ClRecord>& records) {
    std::vector<double> times;
    for (std::size_t i = 1; i < records.size(); ++i) {
        const double chord = (records[i].tip - records[i - 1].tip).norm();
        if (records[i].feed > 0.0) {
            times.push_back(chord / records[i].feed);
        }
    }
    return times;
}

TEST(InverseTime, EveryBlockKeepsItsTimeAndTheBallCentreItsSpeed) {
    const InverseTimeJob& job = inverseTimeJob();
    ASSERT_TRUE(job.result.has_value()) << job.result.error().toString();
    const auto before = recordsOf(job.input), after = recordsOf(job.output);
    ASSERT_EQ(before.size(), after.size());
    const auto timesBefore = blockTimes(before), timesAfter = blockTimes(after);
    ASSERT_EQ(timesBefore.size(), timesAfter.size());
    const double radius = cleanPass().toolRadius;
    double largestSpeedChange = 0.0, largestTipSpeedChange = 0.0;
    for (std::size_t i = 1; i < before.size(); ++i) {
        const double time = timesBefore[i - 1];
        EXPECT_NEAR(timesAfter[i - 1], time, 1e-9 + 1e-6 * time) << "block " << i;
        const auto centre = [&](const auto& records, std::size_t k) {
            return toolpath::ballCentre(records[k], radius);
        };
        const double speedBefore = (centre(before, i) - centre(before, i - 1)).norm() / time;
        const double speedAfter = (centre(after, i) - centre(after, i - 1)).norm() / time;
        largestSpeedChange =
            std::max(largestSpeedChange, std::abs(speedAfter - speedBefore) / speedBefore);
        largestTipSpeedChange = std::max(largestTipSpeedChange,
                                         std::abs(after[i].feed - before[i].feed) / before[i].feed);
    }
    EXPECT_LT(largestSpeedChange, 0.01) << "the cutting speed at the contact point";
    EXPECT_GT(largestTipSpeedChange, 0.05) << "the tip does run at new speeds";
}

TEST(InverseTime, TheAnalysisFollowsTheBlockTimesOfTheProgramAsWritten) {
    const InverseTimeJob& job = inverseTimeJob();
    ASSERT_TRUE(job.result.has_value()) << job.result.error().toString();
    ASSERT_TRUE(job.result->rescheduled.has_value());
    double writtenTime = 0.0, inputTime = 0.0;
    for (const double time : blockTimes(recordsOf(job.output))) {
        writtenTime += time;
    }
    for (const double time : blockTimes(recordsOf(job.input))) {
        inputTime += time;
    }
    const auto& after = job.result->rescheduled->profile;
    const auto& before = job.result->original;
    EXPECT_NEAR(after.cycleTime, writtenTime, 1e-6 * writtenTime);
    EXPECT_NEAR(before.cycleTime, inputTime, 1e-6 * inputTime);
    EXPECT_NEAR(after.cycleTime, before.cycleTime, 1e-6 * before.cycleTime) << "same blocks";
    // An analysis at one constant tip feed over the new tip path would time it differently.
    const double constantFeedGuess = after.pathLength / before.feed;
    EXPECT_GT(std::abs(constantFeedGuess - writtenTime) / writtenTime, 0.01);
}

} // namespace
} // namespace bladeaxis::job::test

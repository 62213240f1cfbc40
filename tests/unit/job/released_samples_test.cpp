// A batch job frees its layers' per-sample curves once it has checked them (JobSpec::
// releaseSamplesOnceRead): what it reports and writes must be what a job that keeps them reports
// and writes, and a job whose own outputs read the curves must keep them.

#include "core/job/demo_program.h"
#include "core/job/job.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace bladeaxis::job {
namespace {

// report.json without its wall times, which differ from run to run.
nlohmann::json reportWithoutTimes(const JobResult& result, const JobSpec& spec) {
    nlohmann::json json = nlohmann::json::parse(reportJsonText(result, &spec));
    const auto strip = [](auto& self, nlohmann::json& node) -> void {
        if (node.is_object()) {
            node.erase("timing");
        }
        if (node.is_structured()) {
            for (auto& child : node) {
                self(self, child);
            }
        }
    };
    strip(strip, json);
    return json;
}

class ReleasedSamples : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto demo = demoProgram(kinematics::defaultBladeMachine());
        ASSERT_TRUE(demo.has_value()) << demo.error().toString();
        std::ofstream(m_scratch.path() / "blade.nc", std::ios::binary) << demo->text;
        m_spec.program = m_scratch.path() / "blade.nc";
        m_spec.toolRadius = demo->toolRadius;
        m_spec.outputProgram = m_scratch.path() / "rescheduled.nc";
    }

    static Result<JobResult> run(const JobSpec& spec) {
        NullProgressSink progress;
        CancelToken cancel;
        return runJob(spec, progress, cancel);
    }

    test::ScratchFolder m_scratch{"bladeaxis_released_samples_"};
    JobSpec m_spec;
};

TEST_F(ReleasedSamples, AJobThatReleasesItsSamplesReportsAndWritesWhatAKeepingJobDoes) {
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    m_spec.releaseSamplesOnceRead = true;
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();

    EXPECT_FALSE(kept->rescheduled->schedule.layerSamplesReleased);
    ASSERT_TRUE(released->rescheduled->schedule.layerSamplesReleased);
    EXPECT_TRUE(released->rescheduled->schedule.layers.front().theta.empty());
    EXPECT_FALSE(kept->original.derivativesReleased);
    ASSERT_TRUE(released->original.derivativesReleased);
    EXPECT_TRUE(released->original.axis(kinematics::AxisId::A).velocity.empty());
    // Taken before the release: the input's T2 and its layers' motion.
    ASSERT_TRUE(kept->timeOptimal.has_value());
    EXPECT_EQ(released->timeOptimal, kept->timeOptimal);
    const auto keptLayers = layerMotionOf(*kept);
    const auto releasedLayers = layerMotionOf(*released);
    ASSERT_EQ(releasedLayers.size(), keptLayers.size());
    for (std::size_t k = 0; k < keptLayers.size(); ++k) {
        EXPECT_EQ(releasedLayers[k].reversalsBefore, keptLayers[k].reversalsBefore);
        EXPECT_EQ(releasedLayers[k].peakVelocityBefore, keptLayers[k].peakVelocityBefore);
        EXPECT_EQ(releasedLayers[k].peakAccelerationBefore, keptLayers[k].peakAccelerationBefore);
    }
    EXPECT_EQ(released->rescheduled->programText, kept->rescheduled->programText);
    EXPECT_EQ(reportWithoutTimes(*released, m_spec), reportWithoutTimes(*kept, m_spec));
    EXPECT_EQ(formatSummary(*released), formatSummary(*kept));
    EXPECT_EQ(released->warnings, kept->warnings);

    ASSERT_TRUE(writeJobOutputs(m_spec, *released).has_value());
    EXPECT_TRUE(std::filesystem::exists(m_spec.outputProgram));
}

TEST_F(ReleasedSamples, AJobWritingItsCsvFilesOrComparingKeepsTheSamplesTheyRead) {
    m_spec.releaseSamplesOnceRead = true;
    m_spec.outputDir = m_scratch.path() / "out";
    const auto withFolder = run(m_spec);
    ASSERT_TRUE(withFolder.has_value()) << withFolder.error().toString();
    EXPECT_FALSE(withFolder->rescheduled->schedule.layerSamplesReleased);
    EXPECT_FALSE(withFolder->original.derivativesReleased);
    ASSERT_TRUE(writeJobOutputs(m_spec, *withFolder).has_value());
    EXPECT_TRUE(std::filesystem::exists(m_spec.outputDir / "layers.csv"));

    m_spec.outputDir.clear();
    m_spec.compare = true;
    m_spec.compareOptimum = false;
    const auto comparing = run(m_spec);
    ASSERT_TRUE(comparing.has_value()) << comparing.error().toString();
    EXPECT_FALSE(comparing->rescheduled->schedule.layerSamplesReleased);
    EXPECT_FALSE(comparing->original.derivativesReleased);
}

TEST_F(ReleasedSamples,
       AnOutputFolderGivenOnlyAfterTheSamplesWereReleasedIsRefusedWithNothingWritten) {
    m_spec.releaseSamplesOnceRead = true;
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();
    ASSERT_TRUE(released->rescheduled->schedule.layerSamplesReleased);

    m_spec.outputDir = m_scratch.path() / "out";
    const Status written = writeJobOutputs(m_spec, *released);
    ASSERT_FALSE(written.has_value());
    EXPECT_EQ(written.error().code, ErrorCode::Internal);
    EXPECT_FALSE(std::filesystem::exists(m_spec.outputProgram));
    EXPECT_FALSE(std::filesystem::exists(m_spec.outputDir));
}

// The check of the input's orientation against the channel reads the curves: it runs before
// they are released, and a program it refuses is refused the same way either way.
TEST_F(ReleasedSamples, TheOrientationCheckRefusesTheSameProgramWhetherOrNotTheSamplesAreReleased) {
    m_spec.check.channelToleranceRad = -1.0; // every CAM orientation counts as outside
    const auto kept = run(m_spec);
    m_spec.releaseSamplesOnceRead = true;
    const auto released = run(m_spec);
    ASSERT_FALSE(kept.has_value());
    ASSERT_FALSE(released.has_value());
    EXPECT_NE(kept.error().message.find("feasible S-theta channel"), std::string::npos)
        << kept.error().toString();
    EXPECT_EQ(released.error().code, kept.error().code);
    EXPECT_EQ(released.error().toString(), kept.error().toString());
}

} // namespace
} // namespace bladeaxis::job

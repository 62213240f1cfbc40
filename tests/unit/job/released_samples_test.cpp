// A job asked for its figures alone (the batch front end: JobSpec::detail) frees its per-sample
// data once it has taken its figures from them: what it reports and writes must be what a job
// that keeps them reports and writes, and a job whose own outputs read them must keep them.

#include "core/job/demo_program.h"
#include "core/job/job.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <string>

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

TEST(Retention, AJobAskedForItsFiguresKeepsOnlyWhatItsOutputsRead) {
    JobSpec spec;
    spec.program = "blade.nc";
    EXPECT_TRUE(retentionOf(spec).inputSamples); // per-sample detail by default: all kept
    EXPECT_TRUE(retentionOf(spec).layerCurves);
    EXPECT_TRUE(retentionOf(spec).newToolAxes);
    EXPECT_TRUE(retentionOf(spec).inputTextInMemory);

    spec.detail = ResultDetail::Figures;
    Retention figures = retentionOf(spec);
    EXPECT_FALSE(figures.inputSamples);
    EXPECT_FALSE(figures.layerCurves);
    EXPECT_FALSE(figures.newToolAxes);
    EXPECT_FALSE(figures.inputTextInMemory);
    EXPECT_FALSE(figures.inputTextAfterRewrite);
    EXPECT_TRUE(figures.writtenText); // no output program to stage it to

    spec.outputCl = "rescheduled.apt"; // made from the new tool axes
    EXPECT_TRUE(retentionOf(spec).newToolAxes);
    EXPECT_FALSE(retentionOf(spec).layerCurves);
    spec.outputDir = "out"; // axes.csv and layers.csv read the samples
    EXPECT_TRUE(retentionOf(spec).inputSamples);
    EXPECT_TRUE(retentionOf(spec).layerCurves);

    JobSpec demo;
    demo.demo = true;
    demo.detail = ResultDetail::Figures;
    EXPECT_TRUE(retentionOf(demo).inputTextAfterRewrite); // demo_blade.nc is written from it
}

TEST_F(ReleasedSamples, AJobThatReleasesItsSamplesReportsAndWritesWhatAKeepingJobDoes) {
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    m_spec.detail = ResultDetail::Figures;
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();

    EXPECT_FALSE(kept->rescheduled->schedule.layerSamplesReleased);
    ASSERT_TRUE(released->rescheduled->schedule.layerSamplesReleased);
    EXPECT_TRUE(released->rescheduled->schedule.layers.front().theta.empty());
    EXPECT_FALSE(kept->original.sampleDataReleased);
    ASSERT_TRUE(released->original.sampleDataReleased);
    EXPECT_TRUE(released->original.axis(kinematics::AxisId::A).velocity.empty());
    // The pass's machine axes went once the input was analysed (only A stayed, for the layers).
    EXPECT_NE(kept->axes, nullptr);
    EXPECT_EQ(released->axes, nullptr);
    EXPECT_EQ(released->original.recordAxes, nullptr);
    // And the schedule's new tool axes once the new motion was analysed: the rewrite wrote them.
    EXPECT_FALSE(kept->rescheduled->schedule.newAxes.empty());
    EXPECT_TRUE(released->rescheduled->schedule.newAxes.empty());
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
    // Staged to its output file as it was written, not kept in memory.
    EXPECT_TRUE(released->rescheduled->programText.empty());
    EXPECT_EQ(released->rescheduled->writtenText().value(), kept->rescheduled->programText);
    EXPECT_EQ(reportWithoutTimes(*released, m_spec), reportWithoutTimes(*kept, m_spec));
    EXPECT_EQ(formatSummary(*released), formatSummary(*kept));
    EXPECT_EQ(released->warnings, kept->warnings);

    ASSERT_TRUE(writeJobOutputs(m_spec, *released).has_value());
    EXPECT_TRUE(std::filesystem::exists(m_spec.outputProgram));
}

TEST_F(ReleasedSamples, AnAnalysisThatReleasesItsSamplesReportsWhatAKeepingOneDoes) {
    m_spec.reschedule = false;
    m_spec.outputProgram.clear();
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    m_spec.detail = ResultDetail::Figures;
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();

    EXPECT_EQ(released->axes, nullptr);
    EXPECT_EQ(released->timeOptimal, kept->timeOptimal);
    EXPECT_EQ(released->originalLostMotion.size(), kept->originalLostMotion.size());
    EXPECT_EQ(reportWithoutTimes(*released, m_spec), reportWithoutTimes(*kept, m_spec));
    EXPECT_EQ(formatSummary(*released), formatSummary(*kept));
}

TEST_F(ReleasedSamples, AJobWritingCutterLocationsKeepsTheNewToolAxesItWritesThemFrom) {
    m_spec.outputCl = m_scratch.path() / "kept.apt";
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    ASSERT_TRUE(writeJobOutputs(m_spec, *kept).has_value());
    m_spec.detail = ResultDetail::Figures;
    m_spec.outputCl = m_scratch.path() / "released.apt";
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();
    ASSERT_TRUE(writeJobOutputs(m_spec, *released).has_value());

    EXPECT_TRUE(released->original.sampleDataReleased);
    EXPECT_EQ(released->rescheduled->schedule.newAxes, kept->rescheduled->schedule.newAxes);
    const auto text = [](const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const std::string keptCl = text(m_scratch.path() / "kept.apt");
    EXPECT_FALSE(keptCl.empty());
    EXPECT_EQ(text(m_scratch.path() / "released.apt"), keptCl);
}

TEST_F(ReleasedSamples, AJobWritingItsCsvFilesOrComparingKeepsTheSamplesTheyRead) {
    m_spec.detail = ResultDetail::Figures;
    m_spec.outputDir = m_scratch.path() / "out";
    const auto withFolder = run(m_spec);
    ASSERT_TRUE(withFolder.has_value()) << withFolder.error().toString();
    EXPECT_FALSE(withFolder->rescheduled->schedule.layerSamplesReleased);
    EXPECT_FALSE(withFolder->original.sampleDataReleased);
    ASSERT_TRUE(writeJobOutputs(m_spec, *withFolder).has_value());
    EXPECT_TRUE(std::filesystem::exists(m_spec.outputDir / "layers.csv"));

    m_spec.outputDir.clear();
    m_spec.compare = true;
    m_spec.compareOptimum = false;
    const auto comparing = run(m_spec);
    ASSERT_TRUE(comparing.has_value()) << comparing.error().toString();
    EXPECT_FALSE(comparing->rescheduled->schedule.layerSamplesReleased);
    EXPECT_FALSE(comparing->original.sampleDataReleased);
}

TEST_F(ReleasedSamples,
       AnOutputFolderGivenOnlyAfterTheSamplesWereReleasedIsRefusedWithNothingWritten) {
    m_spec.detail = ResultDetail::Figures;
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

// A machine whose linear axes have play: their lost motion is counted on the pass's machine
// axes, which a releasing job frees once the layers are known.
constexpr const char* kMachineWithLinearPlay = R"({"schema": "bladeaxis-machine/1",
 "name": "blade machine with play on Y and Z",
 "kinematics": {"type": "table_a_head_b", "pivot_length_mm": 0.0,
  "table_offset_mm": [0, 0, 0], "head_offset_mm": [0, 0, 0], "a_sign": 1, "b_sign": 1},
 "axes": {
  "X": {"min_mm": -1400, "max_mm": 4000, "velocity_mm_s": 500, "acceleration_mm_s2": 3000,
        "jerk_mm_s3": 30000, "backlash_mm": 0.0},
  "Y": {"min_mm": -330, "max_mm": 330, "velocity_mm_s": 500, "acceleration_mm_s2": 3000,
        "jerk_mm_s3": 30000, "backlash_mm": 0.002},
  "Z": {"min_mm": -300, "max_mm": 500, "velocity_mm_s": 500, "acceleration_mm_s2": 3000,
        "jerk_mm_s3": 30000, "backlash_mm": 0.003},
  "A": {"mode": "continuous", "velocity_deg_s": 360, "acceleration_deg_s2": 1800,
        "jerk_deg_s3": 18000, "backlash_deg": 0.005},
  "B": {"min_deg": -87, "max_deg": 87, "velocity_deg_s": 90, "acceleration_deg_s2": 900,
        "jerk_deg_s3": 9000, "backlash_deg": 0.0}}})";

TEST_F(ReleasedSamples, TheLostMotionOfLinearAxesIsTheSameOnceThePassAxesAreReleased) {
    m_spec.machineFile = m_scratch.path() / "machine.json";
    std::ofstream(m_spec.machineFile) << kMachineWithLinearPlay;
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    m_spec.detail = ResultDetail::Figures;
    const auto released = run(m_spec);
    ASSERT_TRUE(released.has_value()) << released.error().toString();

    EXPECT_FALSE(released->axes);
    EXPECT_TRUE(released->original.positions(kinematics::AxisId::Y).empty());
    ASSERT_EQ(kept->originalLostMotion.size(), 3u); // Y, Z and A have play
    EXPECT_GT(kept->originalLostMotion[0].reversals, 0);
    for (std::size_t i = 0; i < kept->originalLostMotion.size(); ++i) {
        EXPECT_EQ(released->originalLostMotion[i].axis, kept->originalLostMotion[i].axis);
        EXPECT_EQ(released->originalLostMotion[i].reversals, kept->originalLostMotion[i].reversals);
    }
    EXPECT_EQ(formatSummary(*released), formatSummary(*kept));
    EXPECT_EQ(reportWithoutTimes(*released, m_spec), reportWithoutTimes(*kept, m_spec));
}

// The check of the input's orientation against the channel reads the curves: it runs before
// they are released, and a program it refuses is refused the same way either way.
TEST_F(ReleasedSamples, TheOrientationCheckRefusesTheSameProgramWhetherOrNotTheSamplesAreReleased) {
    m_spec.check.channelToleranceRad = -1.0; // every CAM orientation counts as outside
    const auto kept = run(m_spec);
    m_spec.detail = ResultDetail::Figures;
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

// A batch job writes the re-scheduled program to its output file while it runs (staged, not in
// place) instead of keeping it in memory: the bytes must be the ones a job that keeps the text
// writes, and a job that ends without writing its outputs must leave nothing behind.

#include "core/base/file_io.h"
#include "core/job/demo_program.h"
#include "core/job/job.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <unistd.h>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

class StagedOutput : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto demo = demoProgram(kinematics::defaultBladeMachine());
        ASSERT_TRUE(demo.has_value()) << demo.error().toString();
        std::ofstream(m_dir / "blade.nc", std::ios::binary) << demo->text;
        m_spec.program = m_dir / "blade.nc";
        m_spec.toolRadius = demo->toolRadius;
        m_spec.outputProgram = m_dir / "rescheduled.nc";
    }
    std::vector<std::string> filesInFolder() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(m_dir)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    test::ScratchFolder m_scratch{"bladeaxis_staged_job_"};
    const fs::path& m_dir = m_scratch.path();
    JobSpec m_spec;
};

Result<JobResult> run(const JobSpec& spec) {
    NullProgressSink progress;
    CancelToken cancel;
    return runJob(spec, progress, cancel);
}

TEST_F(StagedOutput, AStagedProgramIsPutInPlaceWithTheBytesOfAProgramKeptInMemory) {
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    ASSERT_FALSE(kept->rescheduled->stagedProgram);

    m_spec.detail = ResultDetail::Figures;
    const auto staged = run(m_spec);
    ASSERT_TRUE(staged.has_value()) << staged.error().toString();
    ASSERT_TRUE(staged->rescheduled->stagedProgram);
    EXPECT_TRUE(staged->rescheduled->programText.empty());
    EXPECT_FALSE(fs::exists(m_spec.outputProgram)); // staged, not in place
    EXPECT_EQ(staged->rescheduled->maxCentreDeviationMm, kept->rescheduled->maxCentreDeviationMm);
    EXPECT_EQ(*staged->rescheduled->writtenText(), kept->rescheduled->programText);

    ASSERT_TRUE(writeJobOutputs(m_spec, *staged).has_value());
    EXPECT_EQ(*readTextFile(m_spec.outputProgram), kept->rescheduled->programText);
    EXPECT_EQ(filesInFolder(), (std::vector<std::string>{"blade.nc", "rescheduled.nc"}));
}

TEST_F(StagedOutput, AnInputTextDroppedOnceParsedIsReadAgainForTheSameProgram) {
    const auto kept = run(m_spec);
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    m_spec.detail = ResultDetail::Figures;
    const auto dropped = run(m_spec);
    ASSERT_TRUE(dropped.has_value()) << dropped.error().toString();
    EXPECT_TRUE(dropped->programText().empty());
    EXPECT_TRUE(dropped->program.textFile.has_value());
    EXPECT_EQ(*dropped->rescheduled->writtenText(), kept->rescheduled->programText);
}

TEST_F(StagedOutput, AJobWhoseOutputsAreNotWrittenLeavesNothingBehind) {
    m_spec.detail = ResultDetail::Figures;
    {
        const auto staged = run(m_spec);
        ASSERT_TRUE(staged.has_value()) << staged.error().toString();
        ASSERT_TRUE(staged->rescheduled->stagedProgram);
    }
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"blade.nc"});
}

// Cancels the job once the re-scheduling starts, after the output was opened for staging.
class CancelAtRescheduling final : public ProgressSink {
  public:
    explicit CancelAtRescheduling(CancelToken& cancel) : m_cancel(cancel) {}
    void progress(double, std::string_view stage) override {
        if (stage.find("re-scheduling") != std::string_view::npos) {
            m_cancel.requestCancel();
        }
    }
    void warning(std::string_view) override {}

  private:
    CancelToken& m_cancel;
};

TEST_F(StagedOutput, ACancelledJobLeavesNeitherTheProgramNorAPartOfIt) {
    m_spec.detail = ResultDetail::Figures;
    CancelToken cancel;
    CancelAtRescheduling progress(cancel);
    const auto result = runJob(m_spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"blade.nc"});
}

TEST_F(StagedOutput, AnOutputNamingTheInputIsRefusedBeforeAnythingIsWritten) {
    m_spec.detail = ResultDetail::Figures;
    m_spec.outputProgram = m_dir / "." / "blade.nc";
    const std::string before = *readTextFile(m_spec.program);
    const auto result = run(m_spec);
    ASSERT_FALSE(result.has_value());
    // Refused as the bad argument it is, naming both (docs/reliability.md, Writes).
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("output_program and program name the same file"),
              std::string::npos)
        << result.error().message;
    EXPECT_EQ(*readTextFile(m_spec.program), before);
    EXPECT_EQ(filesInFolder(), std::vector<std::string>{"blade.nc"});
}

} // namespace
} // namespace bladeaxis::job

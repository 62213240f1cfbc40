// The re-scheduling stage as a user meets it: a program in, a program out (issue 3, "Results
// and batch"): only tip coordinates and A change, the ball centres survive a re-read, the tool
// stays in the raw channel, A turns one way, and the input is never touched.

#include "core/base/file_io.h"
#include "core/io/nc/gcode_writer.h"
#include "core/job/job.h"
#include "core/job/parameter_schema.h"
#include "core/kinematics/kinematics.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

const fs::path kGcodeProgram = fs::path(BLADEAXIS_TEST_DATA_DIR) / "programs/naca_weak_3rev.nc";
const fs::path kAptProgram = fs::path(BLADEAXIS_TEST_DATA_DIR) / "programs/turbine_2rev.cls";
constexpr double kGeneratedRadius = 8.0; // mm, the radius both programs were generated for

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) {
        lines.push_back(line);
    }
    return lines;
}

Result<JobResult> run(JobSpec spec) {
    NullProgressSink progress;
    CancelToken cancel;
    return runJob(spec, progress, cancel);
}

JobSpec aptSpec() {
    JobSpec spec;
    spec.program = kAptProgram; // the CL file states its cutter (CUTTER/16,8)
    return spec;
}

JobSpec gcodeSpec() {
    JobSpec spec;
    spec.program = kGcodeProgram;
    spec.toolRadius = kGeneratedRadius;
    return spec;
}

// A word of a G-code block, e.g. wordOf("N20 G1 X1.3 A-35.5", 'A') == "A-35.5"; empty if absent.
std::string wordOf(const std::string& block, char letter) {
    std::istringstream words(block);
    for (std::string word; words >> word;) {
        if (word.front() == letter) {
            return word;
        }
    }
    return {};
}

TEST(Reschedule, GcodeOutputChangesOnlyTipCoordinatesAndA) {
    auto result = run(gcodeSpec());
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->rescheduled);
    // The job has released the input's text after the rewrite: compare with the file.
    const auto before = linesOf(readTextFile(gcodeSpec().program).value_or(""));
    const auto after = linesOf(result->rescheduled->programText);
    ASSERT_EQ(before.size(), after.size());
    std::size_t changed = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (before[i] == after[i]) {
            continue;
        }
        ++changed;
        for (char kept : {'N', 'G', 'B', 'F', 'M', 'S', 'T'}) {
            EXPECT_EQ(wordOf(before[i], kept), wordOf(after[i], kept)) << "line " << i + 1;
        }
    }
    EXPECT_GT(changed, before.size() / 2); // the cutting pass was re-oriented
}

// The rewrite is the last reader of the input's text: the job frees it (and where each block's
// words stand) before it reads the written program back, where its memory peaks. The records
// stay for the report, the plots and the comparison; the program can no longer be rewritten.
TEST(Reschedule, AJobReleasesTheInputTextOnceTheProgramIsRewritten) {
    auto result = run(gcodeSpec());
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->rescheduled);
    EXPECT_TRUE(result->programText().empty());
    EXPECT_FALSE(result->rescheduled->programText.empty());
    const auto& gcode = std::get<io::nc::GcodeProgram>(result->program.document);
    EXPECT_TRUE(gcode.sources.empty());
    EXPECT_GE(gcode.path.records.size(), result->pass.first + result->pass.count);
    EXPECT_EQ(io::programsToolTip(result->program, result->pass.first, result->pass.count), false);
    const auto again =
        io::nc::rewriteGcodePass(gcode, result->pass.first, *result->axes, result->machine);
    ASSERT_FALSE(again.has_value());
    EXPECT_EQ(again.error().code, ErrorCode::InvalidArgument);
}

TEST(Reschedule, AnAnalyseOnlyJobKeepsTheInputText) {
    JobSpec spec = gcodeSpec();
    spec.reschedule = false;
    auto result = run(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_EQ(result->programText(), readTextFile(spec.program).value_or(""));
}

TEST(Reschedule, WrittenProgramReproducesEveryBallCentre) {
    for (const JobSpec& spec : {gcodeSpec(), aptSpec()}) {
        auto result = run(spec);
        ASSERT_TRUE(result.has_value()) << result.error().toString();
        ASSERT_TRUE(result->rescheduled);
        EXPECT_LE(result->rescheduled->maxCentreDeviationMm, kCentreDeviationLimitMm)
            << spec.program;
        EXPECT_LT(result->rescheduled->schedule.check.maxCentreErrorMm, 1e-9) << spec.program;
    }
}

TEST(Reschedule, ToolStaysInTheRawChannelAndATurnsOneWay) {
    for (const JobSpec& spec : {gcodeSpec(), aptSpec()}) {
        auto result = run(spec);
        ASSERT_TRUE(result.has_value()) << result.error().toString();
        const RescheduleOutcome& outcome = *result->rescheduled;
        EXPECT_GE(outcome.minChannelClearanceRad, -1e-9) << spec.program;
        EXPECT_GT(result->original.aReversals.count, 0u) << spec.program;
        EXPECT_EQ(outcome.profile.aReversals.count, 0u) << spec.program;
        EXPECT_EQ(outcome.layersKeptOriginal, 0u) << spec.program;
    }
}

TEST(Reschedule, BothPresetsLowerThePeakAAcceleration) {
    for (const char* preset : {"faithful", "best"}) {
        JobSpec spec = gcodeSpec();
        spec.parameters = *presetParameters(preset);
        auto result = run(spec);
        ASSERT_TRUE(result.has_value()) << preset << ": " << result.error().toString();
        const auto& before = result->original.axis(kinematics::AxisId::A);
        const auto& after = result->rescheduled->profile.axis(kinematics::AxisId::A);
        EXPECT_LT(after.peakAcceleration, 0.1 * before.peakAcceleration) << preset;
        EXPECT_LT(result->rescheduled->constantFeed.time, result->constantFeed.time) << preset;
    }
}

class RescheduleOutputs : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("bladeaxis_reschedule_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
        m_input = m_dir / "input.nc";
        fs::copy_file(kGcodeProgram, m_input);
        m_inputText = *readTextFile(m_input);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path m_dir, m_input;
    std::string m_inputText;
};

TEST_F(RescheduleOutputs, WritesProgramLayersAndReport) {
    JobSpec spec = gcodeSpec();
    spec.program = m_input;
    spec.outputProgram = m_dir / "new.nc";
    spec.outputDir = m_dir / "report";
    auto result = run(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(writeJobOutputs(spec, *result));
    EXPECT_EQ(*readTextFile(spec.outputProgram), result->rescheduled->programText);
    const std::string layers = *readTextFile(spec.outputDir / "layers.csv");
    EXPECT_EQ(layers.rfind("record,line,layer,s_mm,theta_original_deg", 0), 0u)
        << layers.substr(0, 200);
    EXPECT_TRUE(fs::exists(spec.outputDir / "report.json"));
    EXPECT_EQ(*readTextFile(m_input), m_inputText);
}

TEST_F(RescheduleOutputs, RefusesToOverwriteTheInputAndLeavesItUnchanged) {
    JobSpec spec = gcodeSpec();
    spec.program = m_input;
    spec.outputProgram = m_dir / "." / "input.nc"; // the same file under another spelling
    const auto refused = run(spec);
    ASSERT_FALSE(refused.has_value()) << "refused before the job runs";
    EXPECT_EQ(refused.error().code, ErrorCode::InvalidArgument);
    // Named only once the job has run (the GUI's export, the API's write_program): the writer
    // refuses it as well.
    JobSpec withoutOutput = spec;
    withoutOutput.outputProgram.clear();
    auto result = run(withoutOutput);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    auto status = writeJobOutputs(spec, *result);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(*readTextFile(m_input), m_inputText);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(m_dir)) {
        ++files;
    }
    EXPECT_EQ(files, 1u) << "no temporary or partial file is left behind";
}

TEST_F(RescheduleOutputs, AnalyseOnlyJobCannotWriteAProgram) {
    JobSpec spec = gcodeSpec();
    spec.program = m_input;
    spec.reschedule = false;
    spec.outputProgram = m_dir / "new.nc";
    auto result = run(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_FALSE(result->rescheduled);
    EXPECT_FALSE(writeJobOutputs(spec, *result).has_value());
    EXPECT_FALSE(fs::exists(spec.outputProgram));
}

} // namespace
} // namespace bladeaxis::job

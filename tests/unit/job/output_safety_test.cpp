// Output safety of the batch front end (issue 39's reliability audit): a run publishes all of its
// outputs or none, and no output may be another output or an input.
#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"
#include "core/base/file_io.h"
#include "tests/support/scratch_folder.h"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_run.h"

namespace bladeaxis::app {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

class OutputSafety : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_EQ(
            run({"--batch", "--generate", m_program.string(), "--revolutions", "2", "-q"}).code,
            kExitOk);
    }
    std::string path(const std::string& name) const { return (m_dir / name).string(); }

    test::ScratchFolder m_scratch{"bladeaxis_output_safety_"};
    const fs::path& m_dir = m_scratch.path();
    const fs::path m_program = m_dir / "blade.nc";
};

TEST_F(OutputSafety, AReportFolderThatCannotTakeReportJsonWritesNoProgram) {
    fs::create_directories(m_dir / "out" / "report.json");
    const CliRun result =
        run({"--batch", m_program.string(), "-o", path("new.nc"), "--out", path("out"), "-q"});
    EXPECT_EQ(result.code, kExitWrite) << result.err;
    EXPECT_NE(result.err.find("report.json"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(m_dir / "new.nc")) << "the program of a run that failed";
    EXPECT_FALSE(fs::exists(m_dir / "out" / "axes.csv"));
}

TEST_F(OutputSafety, ABadClOutputPathWritesNoProgramAndLeavesNoOutputFolder) {
    const CliRun result = run({"--batch", m_program.string(), "-o", path("new.nc"), "--cl-output",
                               path("missing/new.cl"), "--out", path("made/by/run"), "-q"});
    EXPECT_EQ(result.code, kExitWrite) << result.err;
    EXPECT_FALSE(fs::exists(m_dir / "new.nc"));
    EXPECT_FALSE(fs::exists(m_dir / "made")) << "an output folder this run created, left empty";
}

TEST_F(OutputSafety, ASuccessfulRunWritesEveryOutput) {
    const CliRun result = run({"--batch", m_program.string(), "-o", path("new.nc"), "--cl-output",
                               path("new.cl"), "--out", path("out"), "-q"});
    ASSERT_EQ(result.code, kExitOk) << result.err;
    for (const char* name : {"new.nc", "new.cl", "out/report.json", "out/axes.csv"}) {
        EXPECT_TRUE(fs::is_regular_file(m_dir / name)) << name;
    }
}

TEST_F(OutputSafety, AProgramOutputThatIsTheReportIsRefusedNamingBothOptions) {
    const CliRun result = run(
        {"--batch", m_program.string(), "-o", path("out/report.json"), "--out", path("out"), "-q"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("-o and --out (report.json) name the same file"), std::string::npos)
        << result.err;
    EXPECT_FALSE(fs::exists(m_dir / "out"));
}

TEST_F(OutputSafety, AProgramAndClOutputThatAreOneFileAreRefused) {
    writeFile(m_dir / "target.nc", "kept\n");
    fs::create_symlink("target.nc", m_dir / "link.nc");
    for (const auto& [program, cl] : {std::pair{"x.nc", "x.nc"}, std::pair{"x.nc", "./x.nc"},
                                      std::pair{"link.nc", "target.nc"}}) {
        const CliRun result = run(
            {"--batch", m_program.string(), "-o", path(program), "--cl-output", path(cl), "-q"});
        EXPECT_EQ(result.code, kExitUsage) << program << " " << cl << ": " << result.err;
        EXPECT_NE(result.err.find("-o and --cl-output name the same file"), std::string::npos)
            << result.err;
    }
    EXPECT_FALSE(fs::exists(m_dir / "x.nc"));
    EXPECT_EQ(readTextFile(m_dir / "target.nc").value_or(""), "kept\n");
}

TEST_F(OutputSafety, AHardLinkedOutputIsTheSameFile) {
    writeFile(m_dir / "a.nc", "kept\n");
    fs::create_hard_link(m_dir / "a.nc", m_dir / "b.cl");
    const CliRun result =
        run({"--batch", m_program.string(), "-o", path("a.nc"), "--cl-output", path("b.cl"), "-q"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_EQ(readTextFile(m_dir / "a.nc").value_or(""), "kept\n");
}

TEST_F(OutputSafety, AGeneratedProgramOverTheMachineFileIsRefused) {
    const std::string machine = "{\"name\": \"not to be overwritten\"}\n";
    writeFile(m_dir / "m.json", machine);
    const CliRun result =
        run({"--batch", "--generate", path("m.json"), "--machine", path("m.json"), "-q"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("--generate and --machine name the same file"), std::string::npos)
        << result.err;
    EXPECT_EQ(readTextFile(m_dir / "m.json").value_or(""), machine);
}

TEST_F(OutputSafety, AJobFileOutputWithANulCharacterIsRefusedAtItsLine) {
    writeFile(m_dir / "victim.json", "victim\n");
    writeFile(m_dir / "job.json", "{\n  \"schema\": \"bladeaxis-job/1\",\n"
                                  "  \"program\": \"blade.nc\",\n"
                                  "  \"output_program\": \"victim.json\\u0000.nc\"\n}\n");
    const CliRun result = run({"--batch", "--job", path("job.json"), "-q"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("job.json:4:"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("NUL character"), std::string::npos) << result.err;
    EXPECT_EQ(readTextFile(m_dir / "victim.json").value_or(""), "victim\n");
}

// SIGTERM at start-up (before the run's token exists) ended the process by the signal (143):
// the handler is there from main's first line and the signal cancels the run when it starts.
TEST_F(OutputSafety, ASignalBeforeTheRunStartsCancelsItWithExit7AndNothingWritten) {
    installBatchInterruptHandlers();
    std::raise(SIGTERM);
    const CliRun cancelled = run({"--batch", "--generate", path("g.nc"), "-q"});
    const bool writtenWhenCancelled = fs::exists(m_dir / "g.nc");
    const CliRun next = run({"--batch", "--generate", path("g.nc"), "-q"});
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    EXPECT_EQ(cancelled.code, kExitCancelled) << cancelled.err;
    EXPECT_NE(cancelled.err.find("interrupted: nothing was written"), std::string::npos);
    EXPECT_FALSE(writtenWhenCancelled);
    EXPECT_EQ(next.code, kExitOk) << "the signal cancels one run, not every run after it";
    EXPECT_TRUE(fs::exists(m_dir / "g.nc"));
}

// A fixed-head machine, written by the test (the shipped table_a.json's chain and limits).
constexpr const char* kTableAMachine = R"({"schema": "bladeaxis-machine/1",
  "name": "table A, fixed head",
  "kinematics": {"type": "table_a"},
  "axes": {
    "X": {"velocity_mm_s": 400, "acceleration_mm_s2": 2500, "jerk_mm_s3": 25000},
    "Y": {"velocity_mm_s": 400, "acceleration_mm_s2": 2500, "jerk_mm_s3": 25000},
    "Z": {"velocity_mm_s": 400, "acceleration_mm_s2": 2500, "jerk_mm_s3": 25000},
    "A": {"velocity_deg_s": 300, "acceleration_deg_s2": 1500, "jerk_deg_s3": 15000}}}
)";

// `generate --machine table_a.json` wrote B5. (the default tilt) that the same machine then
// refused: a fixed head generates at its own tilt, 0.
TEST_F(OutputSafety, AProgramGeneratedForAFixedHeadIsOneTheSameMachineReschedules) {
    writeFile(m_dir / "table_a.json", kTableAMachine);
    const CliRun generated = run({"--batch", "--generate", path("fixed.nc"), "--machine",
                                  path("table_a.json"), "--revolutions", "2", "-q"});
    ASSERT_EQ(generated.code, kExitOk) << generated.err;
    const CliRun rescheduled = run({"--batch", path("fixed.nc"), "--machine", path("table_a.json"),
                                    "-o", path("new.nc"), "-q"});
    EXPECT_EQ(rescheduled.code, kExitOk) << rescheduled.err;
    const CliRun tilted = run({"--batch", "--generate", path("tilted.nc"), "--machine",
                               path("table_a.json"), "--tilt-deg", "5", "-q"});
    EXPECT_EQ(tilted.code, kExitUsage);
    EXPECT_NE(tilted.err.find("--tilt-deg: the machine (table A, fixed head) has a fixed head"),
              std::string::npos)
        << tilted.err;
}

// "output_cl", documented in docs/python.md and docs/plugins.md, was ignored, as was every key
// the reader did not know (a misspelt "output_programm" wrote nothing without a word).
TEST_F(OutputSafety, AJobFilesOutputClIsWritten) {
    writeFile(m_dir / "job.json", "{\"schema\": \"bladeaxis-job/1\", \"program\": \"blade.nc\", "
                                  "\"output_cl\": \"new.cl\"}\n");
    const CliRun result = run({"--batch", "--job", path("job.json"), "-q"});
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(readTextFile(m_dir / "new.cl").value_or("").find("GOTO/"), std::string::npos);
}

TEST_F(OutputSafety, AnUnknownJobKeyIsRefusedAtItsLineWithTheNearestKnownOne) {
    writeFile(m_dir / "job.json",
              "{\n  \"schema\": \"bladeaxis-job/1\",\n  \"program\": \"blade.nc\",\n"
              "  \"output_programm\": \"new.nc\"\n}\n");
    const CliRun result = run({"--batch", "--job", path("job.json"), "-q"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("job.json:4: output_programm: unknown key in a job file"),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("did you mean \"output_program\"?"), std::string::npos);
    EXPECT_FALSE(fs::exists(m_dir / "new.nc"));
    writeFile(m_dir / "edit.json", "{\"schema\": \"bladeaxis-job/1\", \"program\": \"blade.nc\",\n"
                                   "\"layer_edits\": [{\"layer\": 1, \"margn_deg\": 2}]}\n");
    const CliRun edit = run({"--batch", "--job", path("edit.json"), "-q"});
    EXPECT_EQ(edit.code, kExitUsage) << edit.err;
    EXPECT_NE(edit.err.find("margn_deg: unknown key in a layer edit"), std::string::npos)
        << edit.err;
    EXPECT_NE(edit.err.find("did you mean \"margin_deg\"?"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::app

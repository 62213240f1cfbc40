// A flat or bull-nose cutter a program states: re-orienting it moves its contact point, so the
// job refuses to re-schedule it (exit 5, at the statement's line) unless the job states a ball.

#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"
#include "core/base/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "cli_run.h"

namespace bladeaxis::app {
namespace {

namespace fs = std::filesystem;

// A generated two-revolution program (`format` apt or gcode) whose ball statement is replaced.
fs::path programStating(const std::string& name, const std::string& format,
                        const std::string& ballStatement, const std::string& cutter) {
    const fs::path folder = fs::temp_directory_path() / "bladeaxis_stated_cutter";
    fs::create_directories(folder);
    const fs::path program = folder / name;
    EXPECT_EQ(run({"--batch", "--generate", program.string(), "--format", format, "--revolutions",
                   "2", "-q"})
                  .code,
              kExitOk);
    std::string text = readTextFile(program).value_or("");
    const std::size_t at = text.find(ballStatement);
    EXPECT_NE(at, std::string::npos) << text.substr(0, 300);
    if (at != std::string::npos) {
        text.replace(at, ballStatement.size(), cutter);
    }
    EXPECT_TRUE(writeFileAtomically(program, text));
    return program;
}

int lineOf(const fs::path& file, const std::string& needle) {
    const std::string text = readTextFile(file).value_or("");
    const std::size_t at = text.find(needle);
    return at == std::string::npos
               ? 0
               : 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

TEST(StatedCutter, AnAptBullNoseIsRefusedAtItsLineWithExit5AndNothingWritten) {
    const fs::path program = programStating("bull.apt", "apt", "CUTTER/16,8", "CUTTER/16,2");
    const fs::path output = program.parent_path() / "bull_out.apt";
    fs::remove(output);
    const CliRun result = run({"--batch", program.string(), "-o", output.string(), "-q"});
    EXPECT_EQ(result.code, kExitGeometry) << result.err;
    const std::string where = "bull.apt:" + std::to_string(lineOf(program, "CUTTER/16,2")) + ":";
    EXPECT_NE(result.err.find(where), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("CUTTER/16,2 is not a ball end (corner radius 2 mm"),
              std::string::npos)
        << result.err;
    EXPECT_FALSE(fs::exists(output));
}

TEST(StatedCutter, AFlatEndStatedInAGcodeHeaderIsRefusedAtItsLine) {
    const fs::path program =
        programStating("flat.nc", "gcode", "(ball end R=8 mm", "(T1 D=16. CR=0. flat end mill");
    const CliRun result = run({"--batch", program.string(), "-o",
                               (program.parent_path() / "flat_out.nc").string(), "-q"});
    EXPECT_EQ(result.code, kExitGeometry) << result.err;
    const std::string where = "flat.nc:" + std::to_string(lineOf(program, "(T1 D=16.")) + ":";
    EXPECT_NE(result.err.find(where), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("is not a ball end (corner radius 0 mm, half its diameter 8 mm)"),
              std::string::npos)
        << result.err;
}

TEST(StatedCutter, AJobThatStatesABallOverrulesTheCutterWithAWarning) {
    const fs::path program = programStating("stated.apt", "apt", "CUTTER/16,8", "CUTTER/16,2");
    const CliRun result = run({"--batch", program.string(), "--tool-radius", "8", "-o",
                               (program.parent_path() / "stated_out.apt").string()});
    EXPECT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.err.find("re-scheduled as a ball of 8 mm as the job states"),
              std::string::npos)
        << result.err;
}

TEST(StatedCutter, AnAnalysisOfABullNoseWarnsAndUsesNoBallRadius) {
    const fs::path program = programStating("analysed.apt", "apt", "CUTTER/16,8", "CUTTER/16,2");
    const CliRun result = run({"--batch", program.string(), "--analyse-only"});
    EXPECT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.err.find("the figures use no ball radius"), std::string::npos) << result.err;
}

} // namespace
} // namespace bladeaxis::app

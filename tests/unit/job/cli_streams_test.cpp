// Standard output carries only what a script reads (the program, CL data or JSON), every message
// for a person goes to standard error, and a --json run's refusal is a JSON object
// (docs/cam-integration.md, "The contract"). The JSON is parsed here, as a script would.

#include "app/batch/batch_options.h"
#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"
#include "app/subcommands.h"
#include "core/base/file_io.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

#include "cli_run.h"

namespace bladeaxis::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// A generated program (its header states R = 3 mm) in `folder`.
fs::path generatedProgram(const fs::path& folder) {
    const fs::path program = folder / "blade.nc";
    EXPECT_EQ(
        run({"--batch", "--generate", program.string(), "--revolutions", "2", "--tool-radius", "3"})
            .code,
        kExitOk);
    return program;
}

// The whole of standard output is one JSON document, or the test fails.
Json parsed(const std::string& text) {
    try {
        return Json::parse(text);
    } catch (const Json::exception& error) {
        ADD_FAILURE() << "standard output is not JSON (" << error.what() << "):\n" << text;
        return Json::object();
    }
}

TEST(CliStreams, JsonAndAProgramOnStandardOutputAreRefusedAsAJsonErrorObject) {
    for (const char* output : {"-o", "--cl-output"}) {
        const CliRun result = run({"--batch", "--demo", output, "-", "--json"});
        EXPECT_EQ(result.code, kExitUsage) << result.err;
        EXPECT_NE(result.err.find("would both write to standard output"), std::string::npos)
            << result.err;
        const Json error = parsed(result.out).value("error", Json::object());
        EXPECT_EQ(error.value("code", ""), "InvalidArgument");
        EXPECT_EQ(error.value("exit_code", 0), kExitUsage);
        EXPECT_TRUE(error.at("file").is_null());
        EXPECT_TRUE(error.at("line").is_null());
        EXPECT_NE(error.value("message", "").find("--json"), std::string::npos);
    }
    const CliRun both = run({"--batch", "--demo", "-o", "-", "--cl-output", "-"});
    EXPECT_EQ(both.code, kExitUsage);
    EXPECT_NE(both.err.find("-o - and --cl-output - would both write to standard output"),
              std::string::npos)
        << both.err;
    EXPECT_TRUE(both.out.empty()) << "no JSON asked for";
}

// The JSON report was printed to standard error with -o -, between the warnings; now it is
// always on standard output, alone, and the warnings on standard error.
TEST(CliStreams, TheJsonReportIsAloneOnStandardOutputAndTheWarningsOnStandardError) {
    const fs::path folder = freshFolder("bladeaxis_cli_json_alone");
    const fs::path program = generatedProgram(folder);
    const CliRun result = run({"--batch", program.string(), "--tool-radius", "3.5", "-o",
                               (folder / "new.nc").string(), "--json"});
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.err.find("warning: "), std::string::npos) << "the radii disagree";
    const Json report = parsed(result.out);
    EXPECT_TRUE(report.contains("rescheduled")) << result.out.substr(0, 200);
    fs::remove_all(folder);
}

// A machine file's typo on a known line, through the command line: exit 4, and with --json the
// error object names the file, the line and the nearest key.
TEST(CliStreams, ARefusalWithJsonNamesItsFileLineAndExitCode) {
    const fs::path folder = freshFolder("bladeaxis_cli_json_error");
    std::string machine =
        readTextFile(std::string(BLADEAXIS_SOURCE_DIR) + "/resources/machines/blade_ab.json")
            .value_or("");
    const std::string zAxis = "\"Z\": { \"min_mm\": -300, \"max_mm\"";
    ASSERT_NE(machine.find(zAxis), std::string::npos);
    machine.replace(machine.find(zAxis), zAxis.size(), "\"Z\": { \"min_mm\": -300, \"max_mmm\"");
    const fs::path machineFile = folder / "typo.json";
    ASSERT_TRUE(writeFileAtomically(machineFile, machine));
    const CliRun result = run({"--batch", "--demo", "--machine", machineFile.string(), "--json"});
    EXPECT_EQ(result.code, kExitMachine) << result.err;
    EXPECT_NE(result.err.find("typo.json:15: machine file error: axes.Z.max_mmm: unknown key"),
              std::string::npos)
        << result.err;
    const Json error = parsed(result.out).value("error", Json::object());
    EXPECT_EQ(error.value("code", ""), "MachineFile");
    EXPECT_EQ(error.value("exit_code", 0), kExitMachine);
    EXPECT_EQ(error.value("file", ""), machineFile.string());
    EXPECT_EQ(error.value("line", 0), 15);
    EXPECT_TRUE(error.at("column").is_null());
    EXPECT_NE(error.value("message", "").find("did you mean \"max_mm\"?"), std::string::npos);
    fs::remove_all(folder);
}

TEST(CliStreams, AProgramErrorWithJsonCarriesItsLineAndColumn) {
    const CliRun result = run({"--batch", "-", "--tool-radius", "8", "--json"}, "G1 X\n");
    EXPECT_EQ(result.code, kExitInput);
    const Json error = parsed(result.out).value("error", Json::object());
    EXPECT_EQ(error.value("code", ""), "Parse");
    EXPECT_EQ(error.value("exit_code", 0), kExitInput);
    EXPECT_EQ(error.value("file", ""), "stdin");
    EXPECT_EQ(error.value("line", 0), 1);
    EXPECT_EQ(error.value("column", 0), 5);
}

TEST(CliStreams, ClDataGoToStandardOutputWithTheSummaryOnStandardError) {
    const fs::path folder = freshFolder("bladeaxis_cli_cl_stdout");
    const fs::path program = generatedProgram(folder);
    const fs::path before = fs::current_path();
    fs::current_path(folder); // a file named "-" would appear here
    const CliRun result = run({"--batch", program.string(), "--cl-output", "-"});
    fs::current_path(before);
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_FALSE(fs::exists(folder / "-"));
    EXPECT_NE(result.out.find("GOTO/"), std::string::npos) << result.out.substr(0, 300);
    EXPECT_EQ(result.out.find("reversals"), std::string::npos) << "the summary is not CL data";
    EXPECT_NE(result.err.find("reversals"), std::string::npos) << result.err;
    fs::remove_all(folder);
}

// A gouging program written to a file was refused (exit 5) but one written with -o - was not:
// writeJobOutputs refuses only the files it writes. Both are refused unless --force.
TEST(CliStreams, AGougingProgramIsNotWrittenToStandardOutputEither) {
    const fs::path dir = freshFolder("bladeaxis_cli_gouge_stdout");
    ASSERT_EQ(run({"--batch", "--demo", "--out", dir.string()}).code, kExitOk);
    std::vector<std::string> arguments = gougingDemoArguments(dir, "-");
    const CliRun refused = run(arguments);
    EXPECT_EQ(refused.code, kExitGeometry) << refused.err;
    EXPECT_TRUE(refused.out.empty());
    EXPECT_NE(refused.err.find(": gouge 0."), std::string::npos) << refused.err;
    arguments.emplace_back("--force");
    const CliRun forced = run(arguments);
    EXPECT_EQ(forced.code, kExitOk) << forced.err;
    EXPECT_NE(forced.out.find("M30"), std::string::npos);
    fs::remove_all(dir);
}

TEST(CliStreams, AGeneratedProgramGoesToStandardOutput) {
    const CliRun result = run({"--batch", "--generate", "-", "--revolutions", "2"});
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_TRUE(result.out.starts_with("(BladeAxis synthetic blade program")) << result.out;
    EXPECT_FALSE(fs::exists("-"));
}

TEST(CliStreams, StandardOutputCannotBeAReportFolder) {
    const CliRun result = run({"--batch", "--demo", "--out", "-"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("--out: names a folder"), std::string::npos) << result.err;
}

TEST(CliHabits, AnUnknownOptionNamesTheOptionItMostLikelyMeant) {
    const CliRun result = run({"--batch", "--demo", "--tool-radus", "3"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("bladeaxis: unknown option --tool-radus; did you mean "
                              "--tool-radius?\nRun with --help for usage."),
              std::string::npos)
        << result.err;
    const CliRun grouped = run({"--batch", "--demo", "--margin-dge=3"});
    EXPECT_NE(grouped.err.find("unknown option --margin-dge; did you mean --margin-deg?"),
              std::string::npos)
        << grouped.err;
    const CliRun far = run({"--batch", "--demo", "--frobnicate"});
    EXPECT_NE(far.err.find("unknown option --frobnicate\n"), std::string::npos) << far.err;
    const CliRun json = run({"--batch", "--demo", "--tool-radus", "3", "--json"});
    EXPECT_EQ(parsed(json.out).at("error").value("message", ""),
              "unknown option --tool-radus; did you mean --tool-radius?");
}

TEST(CliHabits, AMistypedCommandIsRefusedNamingTheCommand) {
    const auto none = [](const std::string&) { return false; };
    const auto problem = mistypedSubcommand({"bladeaxis", "reshedule", "x.nc"}, none);
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("unknown command 'reshedule'; did you mean `reschedule`?"),
              std::string::npos)
        << *problem;
    EXPECT_TRUE(mistypedSubcommand({"bladeaxis", "anaylse"}, none).has_value());
    // A file of that name, a command, an option or a program name far from any command: no typo.
    const auto all = [](const std::string&) { return true; };
    EXPECT_FALSE(mistypedSubcommand({"bladeaxis", "reshedule"}, all).has_value());
    EXPECT_FALSE(mistypedSubcommand({"bladeaxis", "reschedule", "x.nc"}, none).has_value());
    EXPECT_FALSE(mistypedSubcommand({"bladeaxis", "--batch"}, none).has_value());
    EXPECT_FALSE(mistypedSubcommand({"bladeaxis", "blade_17.nc"}, none).has_value());
    EXPECT_FALSE(mistypedSubcommand({"bladeaxis"}, none).has_value());
}

// Both run the headless program (main sends --help and --version there), so no display.
TEST(CliHabits, HelpAndVersionAreCommands) {
    EXPECT_EQ(expandSubcommand({"bladeaxis", "help"}),
              (std::vector<std::string>{"bladeaxis", "--help"}));
    EXPECT_EQ(expandSubcommand({"bladeaxis", "version"}),
              (std::vector<std::string>{"bladeaxis", "--version"}));
    std::ostringstream out;
    std::ostringstream err;
    std::istringstream in;
    EXPECT_EQ(runBatchCommandLine(expandSubcommand({"bladeaxis", "help"}), out, err, in), kExitOk);
    EXPECT_NE(out.str().find("  help                        this help"), std::string::npos);
}

TEST(CliHabits, NoProgressIsAnOptionThatExcludesProgress) {
    const auto options = parseBatchOptions({"bladeaxis", "--batch", "--demo", "--no-progress"});
    ASSERT_TRUE(options.has_value()) << options.error().message;
    EXPECT_TRUE(options->noProgress);
    EXPECT_FALSE(options->progress);
    const CliRun both = run({"--batch", "--demo", "--progress", "--no-progress"});
    EXPECT_EQ(both.code, kExitUsage);
    EXPECT_NE(both.err.find("--progress and --no-progress exclude each other"), std::string::npos)
        << both.err;
}

// On a terminal the error was printed over the progress line ("\r 70% ...bladeaxis: ..."):
// the line is ended first. The travel check fails inside the job, while the line is shown.
TEST(CliHabits, AnErrorEndsTheProgressLineFirst) {
    const fs::path folder = freshFolder("bladeaxis_cli_progress_error");
    const CliRun result =
        run({"--batch", "--demo", "--progress", "--machine",
             std::string(BLADEAXIS_SOURCE_DIR) + "/tests/data/machines/short_z_travel.json", "-o",
             (folder / "x.nc").string()});
    EXPECT_EQ(result.code, kExitGeometry) << result.err;
    const std::size_t error = result.err.find("bladeaxis: ");
    ASSERT_NE(error, std::string::npos) << result.err;
    const std::string before = result.err.substr(0, error);
    ASSERT_NE(before.rfind('%'), std::string::npos) << "the progress line was shown";
    // The line shown last ("\r 95% ...\x1b[K") is cleared ("\r\x1b[K") right before the error.
    EXPECT_TRUE(before.ends_with("\x1b[K\r\x1b[K")) << before;
    fs::remove_all(folder);
}

TEST(CliHabits, NumericOptionsShowANumberTypeInTheHelp) {
    const CliRun result = run({"--batch", "--help"});
    for (const char* option : {"--tool-radius FLOAT", "--margin-deg FLOAT", "--feed FLOAT",
                               "--cad-translate FLOAT x 3"}) {
        EXPECT_NE(result.out.find(option), std::string::npos) << option;
    }
    EXPECT_EQ(result.out.find("--tool-radius TEXT"), std::string::npos);
    EXPECT_EQ(result.out.find("x 3 x 3"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::app

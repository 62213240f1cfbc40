#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"
#include "core/base/file_io.h"
#include "core/base/units.h"
#include "core/cad/cad_files.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cli_run.h"

namespace bladeaxis::app {
namespace {

std::string demoProgramText() {
    const auto folder = std::filesystem::temp_directory_path() / "bladeaxis_pipe";
    std::filesystem::create_directories(folder);
    const auto program = folder / "blade.nc";
    EXPECT_EQ(run({"--batch", "--generate", program.string(), "--revolutions", "2"}).code, kExitOk);
    return readTextFile(program).value_or("");
}

TEST(BatchCli, HelpListsTheExitCodes) {
    const CliRun result = run({"--batch", "--help"});
    EXPECT_EQ(result.code, kExitOk);
    EXPECT_NE(result.out.find("Exit codes"), std::string::npos);
    EXPECT_NE(result.out.find("--machine"), std::string::npos);
}

TEST(BatchCli, HelpShowsPresetValuesAsAPersonWritesThem) {
    const CliRun result = run({"--batch", "--help"});
    EXPECT_EQ(result.code, 0);
    EXPECT_NE(result.out.find("(best: -30, faithful: -30)"), std::string::npos);
    EXPECT_EQ(result.out.find("99999999"), std::string::npos) << "a degree value shown in full";
    EXPECT_EQ(result.out.find("00000001"), std::string::npos);
}

TEST(BatchCli, AProgramFromStandardInputIsWrittenToStandardOutputWithTheSummaryOnStandardError) {
    const std::string program = demoProgramText();
    ASSERT_FALSE(program.empty());
    const CliRun result = run({"--batch", "-", "--tool-radius", "8", "-o", "-"}, program);
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_TRUE(result.out.starts_with("(BladeAxis synthetic blade program")) << result.out;
    EXPECT_NE(result.out.find("M30"), std::string::npos);
    EXPECT_NE(result.out, program) << "the orientation was re-scheduled";
    EXPECT_EQ(std::count(result.out.begin(), result.out.end(), '\n'),
              std::count(program.begin(), program.end(), '\n'));
    EXPECT_NE(result.err.find("program      stdin (gcode"), std::string::npos) << result.err;
}

TEST(BatchCli, ABadProgramFromAPipeIsNamedStdinAndLeavesStandardOutputEmpty) {
    const CliRun result = run({"--batch", "-", "--tool-radius", "8", "-o", "-"}, "G1 X\n");
    EXPECT_EQ(result.code, kExitInput);
    EXPECT_TRUE(result.out.empty()) << result.out;
    EXPECT_NE(result.err.find("stdin:1:5: parse error"), std::string::npos) << result.err;
}

// A stream buffer that takes `room` characters and then refuses, as a full disk or /dev/full.
class FullDisk : public std::streambuf {
  public:
    explicit FullDisk(std::size_t room) : m_room(room) {}

  protected:
    int_type overflow(int_type c) override {
        if (m_room == 0) {
            return traits_type::eof();
        }
        --m_room;
        return traits_type::not_eof(c);
    }

  private:
    std::size_t m_room;
};

TEST(BatchCli, AProgramOrReportCutShortOnStandardOutputIsAWriteFailure) {
    for (const char* output : {"-o", "--json"}) {
        std::vector<std::string> arguments{"bladeaxis", "--batch", "--demo", output};
        if (std::string(output) == "-o") {
            arguments.emplace_back("-");
        }
        FullDisk disk(1000);
        std::ostream out(&disk);
        std::ostringstream err;
        std::istringstream in;
        EXPECT_EQ(runBatchCommandLine(arguments, out, err, in), kExitWrite) << output;
        EXPECT_NE(err.str().find("standard output did not take all of"), std::string::npos)
            << err.str();
    }
}

TEST(BatchCli, ProgressShowsTheRunningStageOnOneLineAndClearsIt) {
    const CliRun shown = run({"--batch", "--demo", "--analyse-only", "--progress"});
    ASSERT_EQ(shown.code, kExitOk) << shown.err;
    EXPECT_NE(shown.err.find("\r 30% analysing the original axis motion\x1b[K"), std::string::npos)
        << shown.err;
    EXPECT_TRUE(shown.err.ends_with("\r\x1b[K")) << "the line is cleared before the summary";
    const CliRun silent = run({"--batch", "--demo", "--analyse-only"});
    EXPECT_EQ(silent.err.find('\r'), std::string::npos) << "off when not asked for or not a tty";
}

TEST(BatchCli, VersionPrintsTheVersion) {
    const CliRun result = run({"--batch", "--version"});
    EXPECT_EQ(result.code, kExitOk);
    EXPECT_EQ(result.out.rfind("bladeaxis ", 0), 0u);
}

TEST(BatchCli, NoProgramIsAUsageError) {
    const CliRun result = run({"--batch"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("expected a program"), std::string::npos);
}

TEST(BatchCli, NonNumericToolRadiusIsAUsageError) {
    const CliRun result = run({"--batch", "--demo", "--tool-radius", "8,5"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("--tool-radius: expected a positive number, got '8,5'"),
              std::string::npos);
}

TEST(BatchCli, AnOptionGivenAsAnotherOptionsValueIsAUsageError) {
    const CliRun result = run({"--batch", "--generate", "--out", "somewhere"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("--generate: expected a value, got the option '--out'"),
              std::string::npos)
        << result.err;
    EXPECT_FALSE(std::filesystem::exists("--out"));
}

TEST(BatchCli, AToolRadiusThatReplacesTheFilesCutterIsReported) {
    const std::string program = std::string(BLADEAXIS_TEST_DATA_DIR) + "/programs/turbine_2rev.cls";
    const CliRun result = run({"--batch", program, "--analyse-only", "--tool-radius", "5"});
    EXPECT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.err.find("the ball radius 5 mm given replaces the file's"), std::string::npos)
        << result.err;
}

TEST(BatchCli, AGeneratedProgramIsRescheduledWithTheRadiusItsHeaderStates) {
    const auto folder = std::filesystem::temp_directory_path() / "bladeaxis_cli_generated_radius";
    std::filesystem::create_directories(folder);
    const auto program = folder / "blade.nc";
    ASSERT_EQ(run({"--batch", "--generate", program.string(), "--revolutions", "2", "--tool-radius",
                   "3", "-q"})
                  .code,
              kExitOk);
    ASSERT_NE(readTextFile(program).value_or("").find("(ball end R=3 mm"), std::string::npos);
    const auto output = folder / "blade_rescheduled.nc";
    std::filesystem::remove(output);
    const CliRun result = run({"--batch", program.string(), "-o", output.string(), "--json"});
    ASSERT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.out.find("\"tool_radius_mm\": 3"), std::string::npos);
    EXPECT_EQ(result.err.find("replaces the file's"), std::string::npos) << result.err;
    EXPECT_TRUE(std::filesystem::exists(output));
}

TEST(BatchCli, AToolRadiusThatDisagreesWithTheGeneratorsHeaderIsReportedWithBothRadii) {
    const std::string program =
        std::string(BLADEAXIS_TEST_DATA_DIR) + "/programs/naca_weak_3rev.nc";
    const CliRun result = run({"--batch", program, "--analyse-only", "--tool-radius", "4"});
    EXPECT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.err.find("the ball radius 4 mm given replaces the file's 8 mm (header "
                              "comment)"),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("still states 8 mm"), std::string::npos) << result.err;
}

TEST(BatchCli, AnOutputNamingTheMachineFileIsRefusedAndTheFileKept) {
    const auto folder = std::filesystem::temp_directory_path() / "bladeaxis_cli_machine_output";
    std::filesystem::create_directories(folder);
    const auto machine = folder / "machine.json";
    std::filesystem::copy_file(std::string(BLADEAXIS_SOURCE_DIR) +
                                   "/resources/machines/blade_ab.json",
                               machine, std::filesystem::copy_options::overwrite_existing);
    const auto before = std::filesystem::file_size(machine);
    const CliRun result =
        run({"--batch", "--demo", "--machine", machine.string(), "-o", machine.string()});
    // Refused before the job runs, as the bad command line it is (the writer would refuse too).
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("-o and --machine name the same file"), std::string::npos)
        << result.err;
    EXPECT_EQ(std::filesystem::file_size(machine), before);
}

TEST(BatchCli, UnknownOptionIsAUsageError) {
    EXPECT_EQ(run({"--batch", "--demo", "--frobnicate"}).code, kExitUsage);
}

TEST(BatchCli, MissingMachineFileExitsWithTheMachineCode) {
    const CliRun result = run({"--batch", "--demo", "--machine", "/nonexistent/m.json"});
    EXPECT_EQ(result.code, kExitMachine);
    EXPECT_NE(result.err.find("/nonexistent/m.json"), std::string::npos);
}

TEST(BatchCli, DemoPrintsASummaryWithReversals) {
    const CliRun result = run({"--batch", "--demo"});
    EXPECT_EQ(result.code, kExitOk) << result.err;
    EXPECT_NE(result.out.find("reversals"), std::string::npos);
}

TEST(ExitCodes, EveryErrorCodeMapsToADocumentedExitCode) {
    EXPECT_EQ(exitCodeFor({ErrorCode::Parse, "", {}, {}}), kExitInput);
    EXPECT_EQ(exitCodeFor({ErrorCode::MachineFile, "", {}, {}}), kExitMachine);
    EXPECT_EQ(exitCodeFor({ErrorCode::Infeasible, "", {}, {}}), kExitGeometry);
    EXPECT_EQ(exitCodeFor({ErrorCode::WriteFailed, "", {}, {}}), kExitWrite);
    EXPECT_EQ(exitCodeFor({ErrorCode::Cancelled, "", {}, {}}), kExitCancelled);
    EXPECT_EQ(exitCodeFor({ErrorCode::Internal, "", {}, {}}), kExitInternal);
}

// The demo blade as CAD, moved 0.3 mm along +z into the tool: the input program gouges it, and
// so does the output, which keeps the ball centres. The output is refused (exit 5, nothing
// written) naming the CL point and saying the input already gouges there; --force writes it.
TEST(BatchCli, GougingOutputIsRefusedNamingTheLineUnlessForced) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "bladeaxis_batch_gouge";
    fs::remove_all(dir);
    ASSERT_EQ(run({"--batch", "--demo", "--out", dir.string()}).code, kExitOk);
    const fs::path output = dir / "out.nc";
    const std::vector<std::string> arguments = gougingDemoArguments(dir, output.string());
    const CliRun refused = run(arguments);
    EXPECT_EQ(refused.code, kExitGeometry) << refused.err;
    EXPECT_FALSE(fs::exists(output));
    EXPECT_NE(refused.err.find("demo_blade.nc:"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find(": gouge 0."), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("the input program already gouges there"), std::string::npos)
        << refused.err;
    EXPECT_NE(refused.err.find("warning: the input program's tool already gouges"),
              std::string::npos)
        << refused.err;
    std::vector<std::string> forced = arguments;
    forced.push_back("--force");
    const CliRun written = run(forced);
    EXPECT_EQ(written.code, kExitOk) << written.err;
    EXPECT_TRUE(fs::exists(output));
    fs::remove_all(dir);
}

// The demo blade written with a rotation: Rx(-a) Ry(-b) Rz(-c), the inverse of the documented
// Rz(c) Ry(b) Rx(a) of --cad-rotate-deg a b c. Placed back with those angles it is the program's
// blade and the clearance check passes; as it lies in the file it does not fit (exit 5). Applied
// in the reverse order (Rx Ry Rz) the same angles would leave the blade tilted by 35 deg about y.
TEST(BatchCli, RotatedCadFitsOnlyWhenPlacedBackWithItsRotation) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "bladeaxis_batch_rotated_cad";
    fs::remove_all(dir);
    ASSERT_EQ(run({"--batch", "--demo", "--analyse-only", "--out", dir.string()}).code, kExitOk);
    const double a = units::degToRad(90.0), b = units::degToRad(20.0), c = units::degToRad(15.0);
    cad::Placement inverse;
    inverse.rotation = rotationX(-a) * rotationY(-b) * rotationZ(-c);
    const auto rotated = cad::readCadFile(dir / "demo_blade.step", inverse);
    ASSERT_TRUE(rotated.has_value()) << rotated.error().toString();
    const fs::path rotatedFile = dir / "demo_blade_rotated.step";
    ASSERT_TRUE(cad::writeCadFile(*rotated, rotatedFile, cad::CadFormat::Step));
    const std::vector<std::string> arguments{"--batch",       (dir / "demo_blade.nc").string(),
                                             "--tool-radius", "8",
                                             "--cad",         rotatedFile.string(),
                                             "--out",         (dir / "report").string()};

    const CliRun asWritten = run(arguments);
    EXPECT_EQ(asWritten.code, kExitGeometry) << asWritten.err;
    EXPECT_NE(asWritten.err.find("does not fit the program"), std::string::npos) << asWritten.err;
    EXPECT_NE(asWritten.err.find("--cad-rotate-deg"), std::string::npos) << asWritten.err;

    std::vector<std::string> placed = arguments;
    placed.insert(placed.end(), {"--cad-rotate-deg", "90", "20", "15"});
    const CliRun placedBack = run(placed);
    EXPECT_EQ(placedBack.code, kExitOk) << placedBack.err;
    EXPECT_NE(placedBack.out.find("clearance"), std::string::npos) << placedBack.out;
    fs::remove_all(dir);
}

TEST(BatchCli, CadRotationThatIsNotANumberIsAUsageError) {
    const CliRun result = run({"--batch", "--demo", "--cad-rotate-deg", "90", "0", "x"});
    EXPECT_EQ(result.code, kExitUsage);
    EXPECT_NE(result.err.find("--cad-rotate-deg: expected three numbers (degrees), got 'x'"),
              std::string::npos)
        << result.err;
}

// The scheduling accepts tapers up to 80 deg, the clearance check's shank model below 60: with
// the blade checked, the job stops before scheduling and names the option and the range.
TEST(BatchCli, TaperTheClearanceCheckCannotModelIsAUsageErrorNamingTheOption) {
    const CliRun result = run({"--batch", "--demo", "--taper-deg", "70"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("--taper-deg (job file: parameters.taper_deg) must lie in [0, 60) "
                              "deg, got 70 deg"),
              std::string::npos)
        << result.err;
}

TEST(BatchCli, StickOutShorterThanTheBallIsAUsageErrorNamingTheOption) {
    const CliRun result = run({"--batch", "--demo", "--stick-out", "10"});
    EXPECT_EQ(result.code, kExitUsage) << result.err;
    EXPECT_NE(result.err.find("--stick-out (10 mm) must exceed the ball diameter"),
              std::string::npos)
        << result.err;
}

// A stream without end on standard input (4.5 GB of NUL) took 8.4 GB and ended in exit 1; it is
// capped as a file is, with the file's message (the cap is 4 GiB; a small one here).
TEST(BatchCli, StandardInputLongerThanTheCapIsRefusedAsAFileTooLarge) {
    std::istringstream endless(std::string(5000, '\0'));
    const auto refused = readStandardInput(endless, 4096);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(exitCodeFor(refused.error()), kExitInput);
    EXPECT_EQ(refused.error().toString(),
              "stdin:1:1: parse error: file too large: expected at most 4 GiB of G-code");
    std::istringstream exact(std::string(4096, 'x'));
    EXPECT_EQ(readStandardInput(exact, 4096).value_or("").size(), 4096U);
}

} // namespace
} // namespace bladeaxis::app

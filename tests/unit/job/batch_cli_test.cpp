#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"

#include <gtest/gtest.h>

#include <sstream>

namespace bladeaxis::app {
namespace {

struct CliRun {
    int code;
    std::string out;
    std::string err;
};

CliRun run(std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), "bladeaxis");
    std::ostringstream out;
    std::ostringstream err;
    const int code = runBatchCommandLine(arguments, out, err);
    return {code, out.str(), err.str()};
}

TEST(BatchCli, HelpListsTheExitCodes) {
    const CliRun result = run({"--batch", "--help"});
    EXPECT_EQ(result.code, kExitOk);
    EXPECT_NE(result.out.find("Exit codes"), std::string::npos);
    EXPECT_NE(result.out.find("--machine"), std::string::npos);
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

} // namespace
} // namespace bladeaxis::app

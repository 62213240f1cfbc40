// A minimal plug-in: runs the demo job through the installed facade, writes the re-scheduled
// program, and checks what a plug-in relies on. Exit 0 when every check holds; otherwise the
// failed check on standard error.
#include <bladeaxis/bladeaxis.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

int failed(const std::string& what) {
    std::cerr << "consumer: " << what << '\n';
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        return failed("usage: consumer OUTPUT_FOLDER");
    }
    const std::filesystem::path folder = argv[1];
    int progressCalls = 0;
    bladeaxis::api::Callbacks callbacks;
    callbacks.progress = [&progressCalls](double, std::string_view) { ++progressCalls; };

    auto outcome = bladeaxis::api::runJobJson(R"({"schema": "bladeaxis-job/1", "demo": true})",
                                              folder, callbacks);
    if (!outcome) {
        return failed("demo job failed: " + outcome.error().toString());
    }
    if (progressCalls == 0 || !outcome->rescheduled() || outcome->layers().empty()) {
        return failed("no progress, no re-scheduling or no layers");
    }
    if (outcome->reportJson().find("\"bladeaxis_version\"") == std::string::npos) {
        return failed("report.json without bladeaxis_version");
    }
    const auto written = outcome->writeProgram(folder / "demo_rescheduled.nc");
    if (!written || !std::filesystem::exists(folder / "demo_rescheduled.nc")) {
        return failed("program not written");
    }

    // Errors are values, with the command line's exit code.
    auto missing = bladeaxis::api::runJobJson(
        R"({"schema": "bladeaxis-job/1", "program": "no_such_program.nc"})", folder);
    if (missing || bladeaxis::api::exitCodeFor(missing.error()) != 3) {
        return failed("a missing program is not exit code 3");
    }
    std::cout << "BladeAxis " << bladeaxis::api::version() << ": " << outcome->layers().size()
              << " layers re-scheduled, " << progressCalls << " progress calls\n";
    return EXIT_SUCCESS;
}

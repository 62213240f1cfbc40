// bladeaxis: the desktop application, or with `--batch` (or --help/--version) the batch front
// end, which never creates a QApplication and so needs no display. Any exception that escapes the
// core is a bug; it is caught here, reported and mapped to exit code 1 (docs/architecture.md,
// Conventions). Set BLADEAXIS_TESTING_DISABLE_CATCH_ALL=1 to let it reach the debugger instead.

#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"
#include "app/gui_arguments.h"
#include "app/memory/memory_policy.h"
#include "app/subcommands.h"
#include "ui/run_gui.h"

#include <csignal>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

bool wantsBatch(const std::vector<std::string>& arguments) {
    for (std::size_t index = 1; index < arguments.size(); ++index) {
        const std::string& argument = arguments[index];
        if (argument == "--batch" || argument == "--help" || argument == "-h" ||
            argument == "--version" || argument == "--man") {
            return true;
        }
    }
    return false;
}

} // namespace

int main(int argc, char** argv) {
    // First, so that Ctrl+C at start-up cancels a batch run (exit 7) rather than killing it;
    // the window restores the system's default below.
    bladeaxis::app::installBatchInterruptHandlers();
    // One policy for the window and the batch front end: large blocks go back to the system
    // when freed. The batch front end also kept freed blocks for reuse, which undid this for
    // blocks of 4 MB and more and raised the five-million-block peak by about 100 MB
    // (docs/performance.md, "Memory policy of the executable").
    bladeaxis::app::returnLargeBlocksToTheSystem();
    const std::vector<std::string> given(argv, argv + argc);
    const auto exists = [](const std::string& path) {
        std::error_code ec;
        return std::filesystem::exists(path, ec);
    };
    if (auto problem = bladeaxis::app::mistypedSubcommand(given, exists)) {
        std::cerr << "bladeaxis: " << *problem << '\n';
        return bladeaxis::kExitUsage;
    }
    const std::vector<std::string> arguments = bladeaxis::app::expandSubcommand(given);
    if (!wantsBatch(arguments)) {
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        if (auto problem = bladeaxis::app::checkGuiArguments(arguments, &std::getenv)) {
            std::cerr << "bladeaxis: " << *problem << '\n';
            return bladeaxis::kExitUsage;
        }
        // Qt keeps argc/argv for the application's life: both live until runGui returns.
        std::vector<char*> guiArgv;
        for (const std::string& argument : arguments) {
            guiArgv.push_back(const_cast<char*>(argument.c_str()));
        }
        guiArgv.push_back(nullptr);
        int guiArgc = static_cast<int>(arguments.size());
        return bladeaxis::ui::runGui(guiArgc, guiArgv.data());
    }
    if (std::getenv("BLADEAXIS_TESTING_DISABLE_CATCH_ALL") != nullptr) {
        return bladeaxis::app::runBatchCommandLine(arguments, std::cout, std::cerr);
    }
    try {
        return bladeaxis::app::runBatchCommandLine(arguments, std::cout, std::cerr);
    } catch (const std::exception& exception) {
        std::cerr << "bladeaxis: internal error: " << exception.what() << '\n';
    } catch (...) {
        std::cerr << "bladeaxis: internal error: unknown exception\n";
    }
    return bladeaxis::kExitInternal;
}

// bladeaxis: the batch front end. Any exception that escapes the core is a bug; it is caught
// here, reported and mapped to exit code 1 (style guide §8d). Set
// BLADEAXIS_TESTING_DISABLE_CATCH_ALL=1 to let it reach the debugger instead.

#include "app/batch/batch_runner.h"
#include "app/batch/exit_codes.h"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::vector<std::string> arguments(argv, argv + argc);
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
    return bladeaxis::app::kExitInternal;
}

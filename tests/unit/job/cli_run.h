#pragma once
// The batch command line run in-process, as the CLI tests drive it: the arguments after the
// program name, standard input as text, and the exit code with both streams captured.

#include "app/batch/batch_runner.h"

#include <sstream>
#include <string>
#include <vector>

namespace bladeaxis::app {

struct CliRun {
    int code;
    std::string out;
    std::string err;
};

inline CliRun run(std::vector<std::string> arguments, const std::string& standardInput = {}) {
    arguments.insert(arguments.begin(), "bladeaxis");
    std::ostringstream out;
    std::ostringstream err;
    std::istringstream in(standardInput);
    const int code = runBatchCommandLine(arguments, out, err, in);
    return {code, out.str(), err.str()};
}

} // namespace bladeaxis::app

#pragma once
// The batch command line run in-process, as the CLI tests drive it: the arguments after the
// program name, standard input as text, and the exit code with both streams captured.

#include "app/batch/batch_runner.h"

#include <filesystem>
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

// The demo's program checked against the demo's blade moved 0.3 mm into the tool, so every
// pass gouges: the arguments of that job with its program written to `output` ("-": stdout).
// `folder` holds a `--batch --demo --out folder` run's outputs.
inline std::vector<std::string> gougingDemoArguments(const std::filesystem::path& folder,
                                                     const std::string& output) {
    return {"--batch",
            (folder / "demo_blade.nc").string(),
            "--tool-radius",
            "8",
            "--cad",
            (folder / "demo_blade.step").string(),
            "--cad-translate",
            "0",
            "0",
            "0.3",
            "-o",
            output};
}

} // namespace bladeaxis::app

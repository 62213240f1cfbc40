#pragma once
// Command line of the headless front end. Parsing only: everything it does goes through the
// core job API (core/job/job.h) and the demo generator (core/job/demo_program.h).

#include "core/base/error.h"
#include "core/job/demo_program.h"
#include "core/job/job.h"
#include "core/job/reproduction.h"

#include <filesystem>
#include <string>
#include <vector>

namespace bladeaxis::app {

struct BatchOptions {
    enum class Mode { Analyse, Generate, Reproduce, Help, Version, ManPage };
    Mode mode = Mode::Analyse;
    job::JobSpec job;
    // --generate OUT: write a synthetic blade program instead of analysing one.
    std::filesystem::path generateOutput;
    job::GenerateRequest generate;
    // --reproduce: the comparison over a seeded synthetic family (spec §8.5).
    job::ReproductionSpec reproduction;
    bool printJson = false; // print report.json to stdout instead of the summary
    bool quiet = false;
    // Stage and percentage on standard error, rewritten in place: on when standard error is a
    // terminal, or with --progress (a long --compare is otherwise silent for its duration).
    bool progress = false;
    bool noProgress = false; // --no-progress: not even on a terminal (a CI log that is one)
    std::string helpText;
    std::string manPageText; // with --man: bladeaxis.1, written by the build
};

// Parses argv (argv[0] included). Errors are InvalidArgument with a message for the user.
Result<BatchOptions> parseBatchOptions(const std::vector<std::string>& arguments);

} // namespace bladeaxis::app

#pragma once
// Runs a parsed batch command and returns the process exit code. Output goes to the given
// streams so tests can capture it.

#include "app/batch/batch_options.h"

#include <iosfwd>

namespace bladeaxis::app {

int runBatch(const BatchOptions& options, std::ostream& out, std::ostream& err);

// Parses and runs; the whole `--batch` front end.
int runBatchCommandLine(const std::vector<std::string>& arguments, std::ostream& out,
                        std::ostream& err);

} // namespace bladeaxis::app

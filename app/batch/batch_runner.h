#pragma once
// Runs a parsed batch command and returns the process exit code. Output goes to the given
// streams so tests can capture it.

#include "app/batch/batch_options.h"

#include <iostream>

namespace bladeaxis::app {

// `in` is read only for a program named `-` (standard input in a pipe).
int runBatch(const BatchOptions& options, std::ostream& out, std::ostream& err,
             std::istream& in = std::cin);

// Parses and runs; the whole `--batch` front end.
int runBatchCommandLine(const std::vector<std::string>& arguments, std::ostream& out,
                        std::ostream& err, std::istream& in = std::cin);

} // namespace bladeaxis::app

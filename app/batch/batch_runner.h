#pragma once
// Runs a parsed batch command and returns the process exit code. Output goes to the given
// streams so tests can capture it.

#include "app/batch/batch_options.h"
#include "core/io/nc/gcode_reader.h"

#include <iostream>

namespace bladeaxis::app {

// SIGINT and SIGTERM cancel the batch run (exit 7, nothing written) from here on, for the rest
// of the process: main calls it first, so that no phase (start-up, generation, the exit) ends
// by the signal. A signal before a run starts cancels that run when it starts.
void installBatchInterruptHandlers();

// `in` is read only for a program named `-` (standard input in a pipe).
int runBatch(const BatchOptions& options, std::ostream& out, std::ostream& err,
             std::istream& in = std::cin);

// A program from standard input, capped as a file is (`limit`: io::nc::kMaxProgramBytes, 4 GiB):
// a longer stream is refused once it passes the cap (Parse at stdin:1, the file's message)
// instead of filling memory. Memory held stays within the cap.
Result<std::string> readStandardInput(std::istream& in,
                                      std::size_t limit = io::nc::kMaxProgramBytes);

// Parses and runs; the whole `--batch` front end.
int runBatchCommandLine(const std::vector<std::string>& arguments, std::ostream& out,
                        std::ostream& err, std::istream& in = std::cin);

} // namespace bladeaxis::app

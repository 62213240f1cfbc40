#pragma once
// Documented process exit codes of `bladeaxis --batch` (also in --help, the manual page and
// docs/cam-integration.md); plug-ins get the same through the facade (core/api).

#include "core/base/error.h"

namespace bladeaxis {

enum ExitCode : int {
    kExitOk = 0,
    kExitInternal = 1,  // a bug: please report it with the input
    kExitUsage = 2,     // bad command line
    kExitInput = 3,     // input program missing, unreadable or malformed
    kExitMachine = 4,   // machine file missing or invalid
    kExitGeometry = 5,  // geometry the method cannot handle (NaN, unreachable, infeasible)
    kExitWrite = 6,     // an output could not be written
    kExitCancelled = 7, // stopped on request
};

ExitCode exitCodeFor(const Error& error);

} // namespace bladeaxis

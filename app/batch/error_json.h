#pragma once
// The refusal of a `--json` run as JSON, for the script that asked for machine-readable output:
// {"error": {"code": "MachineFile", "exit_code": 4, "file": "m.json", "line": 14, "column": null,
//  "message": "...", "more": [...]}} (docs/cam-integration.md). Unknown places are null.

#include "core/base/error.h"

#include <string>

namespace bladeaxis::app {

std::string errorJsonText(const Error& error, int exitCode);

} // namespace bladeaxis::app

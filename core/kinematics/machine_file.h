#pragma once
// Loading machine descriptions from JSON (schema "bladeaxis-machine/1", documented in
// docs/machine-file.md). Values in the file carry their units in the key names
// ("velocity_deg_s"); they are converted to mm/rad/s here, once.

#include "core/base/error.h"
#include "core/kinematics/machine_model.h"

#include <filesystem>
#include <string_view>

namespace bladeaxis::kinematics {

// Errors (MachineFile) name the file, the line when it can be found and the JSON path of the
// offending value, e.g. "m.json:14: axes.A.velocity_deg_s: expected a positive number".
Result<MachineModel> parseMachineJson(std::string_view text, std::string_view fileName);
Result<MachineModel> loadMachineFile(const std::filesystem::path& path);

} // namespace bladeaxis::kinematics

#pragma once
// Reading Fanuc-style G-code (words G0/G1, X Y Z A B, constant C, F, G90/G91, G20/G21,
// G93/G94, N, M/S/T/D/H kept verbatim, comments in ( ) and after ;, '%' lines, O numbers,
// '/' block delete treated as active).
//
// Decisions:
// - A CL record is produced for every G0/G1 block with an X Y Z A or B word once X, Y, Z and A
//   are known. B that is never programmed is taken as 0, with a warning in Toolpath::warnings.
//   Leading rapids with partial axes produce no record; a feed move before X, Y, Z and A are
//   known is an error.
// - Rotary words are degrees in the file, radians in ClRecord::axes (A as written).
// - G28/G30/G53 blocks are kept but produce no record: the axes they name become unknown until
//   programmed again. G4 is a dwell (its X is a time).
// - Numbers without a decimal point are taken as mm/deg, not as least input increments.
// - Errors are ErrorCode::Parse with file:line:column; up to 20 are collected (Error::more).

#include "core/base/error.h"
#include "core/io/nc/gcode_program.h"
#include "core/kinematics/machine_model.h"

#include <filesystem>
#include <string_view>

namespace bladeaxis::io::nc {

// The most errors collected before parsing stops.
inline constexpr int kMaxParseErrors = 20;

Result<GcodeProgram> parseGcode(std::string_view text, std::string_view fileName,
                                const kinematics::MachineModel& machine);

// Reads the whole file (FileNotFound / FileUnreadable) and parses it.
Result<GcodeProgram> readGcodeFile(const std::filesystem::path& path,
                                   const kinematics::MachineModel& machine);

} // namespace bladeaxis::io::nc

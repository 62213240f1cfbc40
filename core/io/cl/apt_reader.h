#pragma once
// Reading APT / ISO 4343 CLDATA and Siemens NX CLSF text into a toolpath.
// Units: the file's UNITS (mm or inches, feeds per minute) become mm and mm/s.

#include "core/base/error.h"
#include "core/io/cl/apt_program.h"

#include <filesystem>
#include <string_view>

namespace bladeaxis::io::cl {

// Most errors reported for one file; the first is the Error, the others go to Error::more.
constexpr int kMaxReportedErrors = 20;

// Parses CL text. `fileName` names the source in diagnostics ("blade.cls:7:12: ...").
// Errors (ErrorCode::Parse): malformed GOTO/FEDRAT/UNITS/CUTTER/TLDATA, NaN or infinite
// numbers, a zero tool axis, a `$` continuation at the end of the file, a feed GOTO before any
// FEDRAT, binary bytes, an empty file or one without any GOTO.
Result<AptProgram> parseApt(std::string_view text, std::string_view fileName);

// Reads and parses a file; diagnostics name it by `path`.
Result<AptProgram> readAptFile(const std::filesystem::path& path);

} // namespace bladeaxis::io::cl

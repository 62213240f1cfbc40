#pragma once
// Reading APT / ISO 4343 CLDATA and Siemens NX CLSF text into a toolpath.
// Units: the file's UNITS (mm or inches, feeds per minute) become mm and mm/s.

#include "core/base/error.h"
#include "core/io/cl/apt_program.h"
#include "core/io/read_options.h"

#include <filesystem>
#include <string_view>

namespace bladeaxis::io::cl {

// Most errors reported for one file; the first is the Error, the others go to Error::more.
constexpr int kMaxReportedErrors = 20;

// Parses CL text. `fileName` names the source in diagnostics ("blade.cls:7:12: ...").
// Errors (ErrorCode::Parse): malformed GOTO/FEDRAT/UNITS/CUTTER/TLDATA/MSYS/GODLTA/FROM, NaN
// or infinite numbers, a zero tool axis, a `$` continuation at the end of the file, a feed
// GOTO before any FEDRAT without a feed in the options (reported once), binary bytes, an empty
// file or one without any GOTO, and statements that move the tool in ways BladeAxis does not
// follow: circles (CIRCLE), APT source motion (GO, GOFWD, GOLFT, GORGT, GOBACK, GOUP, GODOWN,
// INDIRV, INDIRP, PSIS), each naming its line and what to post instead.
// Applied: MSYS local frames (GOTO numbers are local, records are world), GODLTA incremental
// moves and FROM start points.
// `options.feedMmPerS` feeds CL data that programs no FEDRAT (bare GOTO lists).
Result<AptProgram> parseApt(std::string_view text, std::string_view fileName,
                            const ReadOptions& options = {});

// Reads and parses a file; diagnostics name it by `path`.
Result<AptProgram> readAptFile(const std::filesystem::path& path, const ReadOptions& options = {});

} // namespace bladeaxis::io::cl

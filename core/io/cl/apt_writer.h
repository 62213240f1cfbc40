#pragma once
// Writing APT / CLSF: a minimal-diff rewrite of a program that was read, and a fresh CL file.

#include "core/base/error.h"
#include "core/io/cl/apt_program.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::io::cl {

// The program's text with the tip and tool axis of every GOTO replaced by `newRecords`
// (same count and order as program.path.records; only tip and axis are used).
// Numbers whose new value prints the same as the old one keep their bytes; changed numbers
// keep their decimals; layout, `$` continuations, comments and line endings are untouched.
// A GOTO/x,y,z whose axis changes gains ",i,j,k" (and a MULTAX/ON line before it when
// MULTAX is not on there). Errors (InvalidArgument): size mismatch, non-finite values.
Result<std::string> rewriteApt(const AptProgram& program,
                               std::span<const toolpath::ClRecord> newRecords);

// rewriteApt written atomically to `out`; refuses (WriteFailed) to overwrite the program's
// source file.
Status writeAptFile(const std::filesystem::path& out, const AptProgram& program,
                    std::span<const toolpath::ClRecord> newRecords);

struct AptEmitOptions {
    int decimals = 6; // digits after the point for coordinates and feeds (clamped to 0..17)
    std::string partName = "BLADEAXIS";
    std::optional<double> toolRadius;  // ball radius in mm; written as CUTTER/2r,r
    std::vector<std::string> comments; // written as `$$` lines after PARTNO
};

// A fresh CL file in mm: PARTNO, comments, UNITS/MM, CUTTER, MULTAX/ON, FEDRAT/MMPM when the
// feed changes, RAPID before rapid GOTOs, GOTO/x,y,z,i,j,k, END, FINI.
// Expects finite records (a validated toolpath); a feed record with feed <= 0 keeps the
// previous FEDRAT. options.toolRadius, when absent, falls back to path.toolRadius.
std::string emitApt(const toolpath::Toolpath& path, const AptEmitOptions& options);

} // namespace bladeaxis::io::cl

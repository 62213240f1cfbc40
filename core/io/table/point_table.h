#pragma once
// Point tables: the plainest CL data, one tool position per line as numbers, the tool tip x y z
// (mm) and the tool axis i j k, separated by blanks, commas or semicolons (docs/table-format.md).
// A header line names the columns in any order (x, y, z, i, j, k, and f for a feed in mm/min;
// other columns are kept and ignored); without one, six numbers per line are x y z i j k, and
// any other count needs ReadOptions::tableColumns. Lines starting with '#' and blank lines are
// comments. Every record is a feed move.

#include "core/base/error.h"
#include "core/io/read_options.h"
#include "core/toolpath/toolpath.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::io::table {

// Where the six numbers of one record sit in TableProgram::text.
struct TableRecordSource {
    std::size_t lineBegin = 0;
    std::array<std::uint32_t, 6> begin{}; // x y z i j k, offsets from lineBegin
    std::array<std::uint16_t, 6> length{};
};

struct TableProgram {
    toolpath::Toolpath path; // format Table; one record per data line
    std::string text;        // the original file, byte for byte
    std::vector<TableRecordSource> sources;
};

// Errors (ErrorCode::Parse, file:line:column): a header without x, y, z, i, j and k, a line
// with another number of fields than the header, a field that is not a finite number, a zero
// tool axis, no feed (no f column and no ReadOptions::feedMmPerS, reported once), no data line.
Result<TableProgram> parsePointTable(std::string_view text, std::string_view fileName,
                                     const ReadOptions& options = {});

// The table with the records' tips and axes, every other byte kept; a changed number keeps
// its column's decimals. Errors: InvalidArgument (record count, non-finite values).
Result<std::string> rewritePointTable(const TableProgram& program,
                                      std::span<const toolpath::ClRecord> records);

// True when the text looks like a point table: its first data lines hold only numbers (3 or
// more), with at most a header line of names before them.
bool looksLikePointTable(std::string_view text);

} // namespace bladeaxis::io::table

#pragma once
// Reading Fanuc-style G-code (words G0/G1, X Y Z A B, constant C, F, G90/G91, G20/G21,
// G93/G94, N, M/S/T/D/H kept verbatim, comments in ( ) and after ;, '%' lines, O numbers,
// '/' block delete treated as active).
//
// The same reader takes Siemens Sinumerik 840D and Heidenhain conversational programs
// (dialect.h decides which, ReadOptions::dialect overrides; detail/sinumerik_scanner.h and
// detail/heidenhain_scanner.h list what each reads and refuses). Their rotary words are degrees,
// their numbers without a decimal point whole units, and while tool-tip programming is on
// (TRAORI, M128, FUNCTION TCPM) X Y Z are the tip in the workpiece frame.
//
// Decisions:
// - A CL record is produced for every G0/G1 block with an X Y Z A or B word once X, Y, Z and A
//   are known. B that is never programmed is taken as 0, with a warning in Toolpath::warnings.
//   Leading rapids with partial axes produce no record; a feed move before X, Y, Z and A are
//   known is an error.
// - Rotary words are degrees in the file unless ReadOptions::angleUnit or a header comment
//   before the first rotary word ("(ANGLES IN RADIANS)") says radians; radians in
//   ClRecord::axes (A as written). A program whose |A| and |B| all stay within 2 pi could be
//   either and is refused unless the unit is stated. The writer keeps the unit.
// - Subprogram calls and returns (M98, M99), macro calls (G65, G66), macro variables (#) and
//   expressions ([...]) are refused, and so is any block after the program end (M2/M30): the
//   reader would miss or misplace their moves.
// - G28/G30/G53 blocks are kept but produce no record: the axes they name become unknown until
//   programmed again. G4 is a dwell (its X is a time).
// - Axis words without a decimal point follow the machine file's `integer_words` rule: least
//   input increments, whole units, or (the default) whole units with a program that mixes both
//   styles refused. A UTF-8 byte order mark and CRLF line ends read like plain text.
// - Errors are ErrorCode::Parse with file:line:column; up to 20 are collected (Error::more).

#include "core/base/error.h"
#include "core/io/nc/gcode_program.h"
#include "core/io/read_options.h"
#include "core/io/read_watch.h"
#include "core/kinematics/machine_model.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace bladeaxis::io::nc {

// The most errors collected before parsing stops.
inline constexpr int kMaxParseErrors = 20;

// The largest program read (4 GiB less one byte: line offsets are 32-bit), from a file or a
// stream, and the error past it (Parse, at `fileName`:1).
inline constexpr std::size_t kMaxProgramBytes = 0xFFFF'FFFFU;
Error programTooLarge(std::string_view fileName);

Result<GcodeProgram> parseGcode(std::string_view text, std::string_view fileName,
                                const kinematics::MachineModel& machine,
                                const ReadOptions& options = {});

// parseGcode of text the program then keeps as it is: a large program's text is not copied.
// The `watch` hears how far the read has come and may stop it (ErrorCode::Cancelled).
Result<GcodeProgram> parseOwnedGcode(std::string text, std::string_view fileName,
                                     const kinematics::MachineModel& machine,
                                     const ReadOptions& options = {}, const ReadWatch& watch = {});

// A run of consecutive records of a streamed program; `first` is the index of records[0] in the
// whole program. A failed status stops the read, which returns it (a cancelled job, a check
// that has seen enough).
using RecordChunkConsumer =
    std::function<Status(std::size_t first, std::span<const toolpath::ClRecord> records)>;

// How far a streamed read has read its text: nothing before `offset` is read again. A reader
// of a large mapped file gives those pages back (MappedText::releaseBefore).
using TextReadUpTo = std::function<void(std::size_t offset)>;

// The most records a streamed read hands on at a time.
inline constexpr std::size_t kStreamChunkRecords = 4096;

// Reads `text` as parseGcode does (the same records, checks and errors) but keeps none of its
// records: they go to `consume` in order, in runs of at most kStreamChunkRecords. A check that
// looks at each record once, such as reading a written program back, then holds a few hundred
// kilobytes instead of about 140 bytes per record. After each run it tells `readUpTo` how far
// it has read. Returns the number of records. On an error
// `consume` may already have seen the records before it.
Result<std::size_t> streamGcodeRecords(std::string_view text, std::string_view fileName,
                                       const kinematics::MachineModel& machine,
                                       const ReadOptions& options,
                                       const RecordChunkConsumer& consume,
                                       const TextReadUpTo& readUpTo = {});

// Reads the whole file (FileNotFound / FileUnreadable) and parses it.
Result<GcodeProgram> readGcodeFile(const std::filesystem::path& path,
                                   const kinematics::MachineModel& machine,
                                   const ReadOptions& options = {});

} // namespace bladeaxis::io::nc

#pragma once
// Minimal-diff rewriting of a parsed G-code program with new machine axes.
//
// Every block whose words do not change is copied byte for byte (line endings, a missing final
// newline and all). A word changes only when its new value, formatted the way the file writes
// that word (decimals, leading zero, explicit '+'), differs from its text; it keeps its
// position. A block without a word for an axis gets one inserted, in X Y Z A B order, when the
// new value differs from the modal value in effect. G91 blocks get recomputed increments, G20
// blocks inch values, and modulo A axes values in [0, 360). F words are never changed.
// Sinumerik and Heidenhain programs are written in their own words: a rotary word keeps its
// form (A=DC(..) stays DC, IA stays incremental; an inserted word takes the form the program
// used last), Heidenhain words keep their sign. A new position the form cannot reach the way
// the control turns (a DC step of 180 deg or more, ACP backwards) is ErrorCode::CheckFailed
// naming the block, and nothing is returned.

#include "core/base/error.h"
#include "core/base/forward_text.h"
#include "core/io/nc/gcode_program.h"
#include "core/kinematics/machine_model.h"

#include <filesystem>
#include <functional>
#include <span>
#include <string>

namespace bladeaxis::io::nc {

// newAxes: one entry per program.path.records entry (same order), machine axes as in
// ClRecord::axes. Errors (InvalidArgument): wrong count or a non-finite value; no partial output.
Result<std::string> rewriteGcode(const GcodeProgram& program,
                                 std::span<const kinematics::MachineAxes> newAxes,
                                 const kinematics::MachineModel& machine);

// Told, every few megabytes of a rewrite, how far it has read the program: it reads the text
// before `textEnd` and the block sources (and programmed feeds) before `blockEnd` no more. A
// job gives those pages back as it goes (io::LoadedProgram::releaseRewriteSourcesBefore).
using RewrittenUpTo = std::function<void(std::size_t textEnd, std::size_t blockEnd)>;

// Takes the written text in order, a few megabytes at a time (a job appends it to the output
// file it stages); an error stops the rewrite with it.
using WrittenPiece = std::function<Status(std::string_view piece)>;

// How a rewrite reads and writes when the text is not all in memory.
struct RewriteStreams {
    RewrittenUpTo rewrittenUpTo;
    // Given, every byte of the written text goes there and the rewrite returns an empty text:
    // the written program is never whole in memory.
    WrittenPiece writtenPiece;
    // Given, the program's text is read again from this file (refused when it is no longer the
    // file that was parsed) instead of from program.text, which may then be empty.
    std::optional<FileSnapshot> textFile;
};

// rewriteGcode of one pass: records [passFirst, passFirst + passAxes.size()) get passAxes, every
// other record is written with the axes it was read with (its text is unchanged).
Result<std::string> rewriteGcodePass(const GcodeProgram& program, std::size_t passFirst,
                                     std::span<const kinematics::MachineAxes> passAxes,
                                     const kinematics::MachineModel& machine,
                                     const RewriteStreams& streams = {});

// rewriteGcode, then an atomic write that refuses to overwrite the program's source file.
Status writeGcodeFile(const std::filesystem::path& out, const GcodeProgram& program,
                      std::span<const kinematics::MachineAxes> newAxes,
                      const kinematics::MachineModel& machine);

} // namespace bladeaxis::io::nc

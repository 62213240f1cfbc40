#pragma once
// A generator of the awkward programs real CAM systems and posts write, made from one clean
// synthetic blade pass (no downloaded data): five-axis CL whose tilt varies, a tool axis from
// below the surface, B noise, rotary words in radians, micro-chords, headerless GOTO lists,
// x y z i j k tables (whitespace and CSV), CRLF line ends and `$` continuation lines. Each keeps
// the clean pass's ball centres unless its point is to break them, so an accepted variant must
// re-schedule to the clean program's result.

#include "core/kinematics/machine_model.h"
#include "core/toolpath/toolpath.h"

#include <string>

namespace bladeaxis::job::test {

// The clean pass: a short high-camber blade program (two revolutions) as CL records in the
// workpiece frame, with its ball radius and feed.
struct CleanPass {
    toolpath::Toolpath path;
    double toolRadius = 0.0; // mm
    double feedMmPerMin = 0.0;
};

const CleanPass& cleanPass();

enum class LineEnd { Lf, Crlf };

struct AptStyle {
    bool header = true;         // PARTNO, UNITS, CUTTER, MULTAX, FEDRAT, FINI
    bool continuations = false; // every GOTO split over two lines with `$`
    LineEnd lineEnd = LineEnd::Lf;
};

// APT CL data of the records (GOTO/x,y,z,i,j,k at 6 decimals).
std::string aptText(const toolpath::Toolpath& path, double toolRadius, double feedMmPerMin,
                    const AptStyle& style = {});

// A point table: one line "x y z i j k" per record (`separator` between the numbers), with a
// header line naming the columns when `header` is set.
std::string tableText(const toolpath::Toolpath& path, char separator, bool header);

enum class RotaryUnit { Degrees, Radians };
enum class FeedMode { PerMinute, InverseTime }; // G94 (one F) or G93 (F on every block)

// ISO G-code of the records on `machine` (inverse kinematics, A continuous), rotary words in
// `unit`, a program end M30; `bNoiseDeg` adds +-that much, alternating, to every B word. In
// inverse time every block's F is the feed over its tip chord (1/min), as a post writes it for
// a constant tip feed.
std::string gcodeText(const toolpath::Toolpath& path, const kinematics::MachineModel& machine,
                      double feedMmPerMin, RotaryUnit unit, double bNoiseDeg = 0.0,
                      FeedMode feedMode = FeedMode::PerMinute);

// The same ball centres with the tilt B rising linearly by `extraTiltDeg` along the pass: a
// five-axis program (each tool axis turned about the in-plane normal, the tip moved to keep Q).
toolpath::Toolpath withVaryingTilt(const toolpath::Toolpath& path, double toolRadius,
                                   double extraTiltDeg);

// The same ball centres with every tool axis mirrored through the rotary axis' plane
// (i, j, -k)...: the tool comes from below the surface on the part of the pass above it.
toolpath::Toolpath withAxisFromBelow(const toolpath::Toolpath& path, double toolRadius);

// A chord of `chordMm` inserted every `every` records, on the straight segment to the next
// record (centre and axis interpolated linearly, axis renormalised): what posts write where a
// CAM system splits a move at a tolerance boundary.
toolpath::Toolpath withMicroChords(const toolpath::Toolpath& path, double toolRadius,
                                   double chordMm, int every);

} // namespace bladeaxis::job::test

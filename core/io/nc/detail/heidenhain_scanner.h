#pragma once
// Scanning a Heidenhain conversational (.h) line into words. A line is an optional block number
// and one statement:
// - "L X+10 Y-2.5 Z+3 A+45 B+15 R0 F3000 M3": a straight move, scanned as a G1 (G0 with FMAX)
//   block with its axis words ("IA+5" is an incremental rotary word), F / FMAX / FAUTO and M
//   words; M126/M127 and M128/M129 become BlockControl bits.
// - BEGIN PGM (its MM or INCH as G21 / G20), END PGM (the program end), BLK FORM, TOOL DEF
//   (number, R), TOOL CALL (number, F for FAUTO, DR), FUNCTION TCPM / FUNCTION RESET TCPM,
//   CYCL DEF 32 (tolerance), PLANE RESET, FUNCTION MODE, STOP, comments (';' and '*'):
//   read, kept verbatim.
// Refused, naming the statement: arcs (CC C CR CT CP RND CHF), radius compensation RL/RR,
// approach and departure (APPR DEP), LN vectors, Q parameters and FN, labels and calls,
// datum shift, rotation, mirror, scaling and tilted planes (CYCL DEF 7/8/10/11/19, PLANE),
// feeds per revolution or tooth (FU FZ), spatial-angle TCPM (AXIS SPAT), incremental linear
// words (IX IY IZ), and any statement not known.

#include "core/io/nc/detail/block_scanner.h"

namespace bladeaxis::io::nc::detail {

std::optional<ScanIssue> scanHeidenhainBlock(std::string_view line, ScannedBlock& block);

} // namespace bladeaxis::io::nc::detail

#pragma once
// Scanning a Siemens Sinumerik 840D block into words. Besides the ISO words ("N10 G1 X10.5
// F3000"): ';' comments, axis words with '=' ("A=45", "A=DC(45)", "A=ACP(45)", "A=ACN(45)",
// "A=AC(45)", "A=IC(5)"), the instructions that change how a four-axis program reads (TRAORI
// and TRAFOOF as BlockControl bits, M17 and RET as the program end), and instructions that do
// not move the axes kept verbatim (G642, CYCLE832(..), MSG(".."), T="..", ORIWKS, SOFT...).
//
// Refused, naming the instruction: R-parameters, variables and expressions in words, frames
// (TRANS, ROT, CYCLE800...), control flow and subprogram calls, orientation vectors (A3=),
// incremental or absolute-function linear words (X=IC(..)), and any instruction not known to be
// harmless: a program BladeAxis does not understand is not rewritten.

#include "core/io/nc/detail/block_scanner.h"

namespace bladeaxis::io::nc::detail {

std::optional<ScanIssue> scanSinumerikBlock(std::string_view line, ScannedBlock& block);

} // namespace bladeaxis::io::nc::detail

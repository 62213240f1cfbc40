#pragma once
// What each G code means to a four-axis reader. Codes are held as ten times their number, so
// that G1 = 10, G43.4 = 434 and G54.1 = 541.

#include <string>

namespace bladeaxis::io::nc::detail {

enum class GKind {
    Rapid,              // G0
    Linear,             // G1
    Dwell,              // G4: its X/P word is a time
    ReferenceReturn,    // G28/G30: axes named become unknown
    MachineCoordinates, // G53: axes named are machine coordinates, unknown in W
    Inch,               // G20
    Metric,             // G21
    Absolute,           // G90
    Incremental,        // G91
    InverseTime,        // G93
    PerMinute,          // G94
    ToolTipOn,          // G43.4: tool centre point control, X Y Z the tip in the workpiece frame
    ToolTipOff,         // G49: tool length compensation and tool centre point control off
    NoOp,               // plane, compensation cancel, work offsets, look-ahead...: no effect here
    Unsupported,        // rejected with a reason
};

struct GCodeInfo {
    GKind kind = GKind::Unsupported;
    const char* reason = nullptr; // for Unsupported: why, and what to do instead
};

// What gCodeTimesTen gives for a value that is no G number (negative, or more than one decimal).
inline constexpr int kNotAGCode = -1;

// Ten times a G word's value (G1 = 10, G43.4 = 434), or kNotAGCode. An int rather than an
// optional: GCC builds a returned std::optional<int> in memory and reads it back wider than it
// wrote it, a stall on every G word of a program.
int gCodeTimesTen(double value);

GCodeInfo classifyGCode(int codeTimesTen);

// The same for Sinumerik's own G codes: G70/G71 and G700/G710 for inch and metric, G153 for
// machine coordinates, its continuous-path, exact-stop and frame-suppression codes as no-ops;
// the ISO-mode G20/G21 are refused.
GCodeInfo classifySinumerikGCode(int codeTimesTen);

// "G43.4" for 434.
std::string gCodeName(int codeTimesTen);

} // namespace bladeaxis::io::nc::detail

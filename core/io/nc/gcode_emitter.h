#pragma once
// A fresh G-code program from a toolpath (used by the demo blade generator).
//
// Layout: the header comments as "(...)" lines, "G21 G90 G94", one block per record
// ("N10 G1 X.. Y.. Z.. A.. B.. F.."; G0 for rapids; F in mm/min only when it changes), "M30".
// Axes come from kinematics::inverseKinematics with A unwrapped continuously from record to
// record; a modulo machine gets A in [0, 360).

#include "core/base/error.h"
#include "core/kinematics/machine_model.h"
#include "core/toolpath/toolpath.h"

#include <string>
#include <vector>

namespace bladeaxis::io::nc {

struct GcodeEmitOptions {
    int linearDecimals = 4;  // digits after the point for X Y Z (mm)
    int angularDecimals = 4; // digits after the point for A B (deg)
    bool blockNumbers = true;
    int blockNumberStep = 10;
    std::vector<std::string> headerComments; // one "(...)" line each; parentheses are replaced
};

// Errors: InvalidArgument (bad options, a feed move without a positive feed before any F),
// Geometry (a record IK cannot solve, naming its index).
Result<std::string> emitGcode(const toolpath::Toolpath& path,
                              const kinematics::MachineModel& machine,
                              const GcodeEmitOptions& options);

} // namespace bladeaxis::io::nc

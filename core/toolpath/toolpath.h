#pragma once
// The toolpath model every reader produces and every stage consumes: ordered cutter-location
// (CL) records in the workpiece frame W, each with its provenance in the source file.
// Units: mm, rad, s (feeds are stored in mm/s).

#include "core/geometry/vec.h"
#include "core/kinematics/machine_model.h"

#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::toolpath {

enum class MotionKind { Rapid, Feed };

enum class SourceFormat { Gcode, Apt, Table };

struct ClRecord {
    Vec3 tip = Vec3::Zero();   // O: tool tip (lowest point of the ball) in W, mm
    Vec3 axis = Vec3::UnitZ(); // V: unit tool axis from the tip towards the spindle, in W
    // The machine axes as programmed, when the record comes from an NC program (A unwrapped
    // as written: continuous programs keep their cumulative A).
    std::optional<kinematics::MachineAxes> axes;
    double feed = 0.0; // programmed tip feed in mm/s; 0 when unknown (rapids)
    MotionKind motion = MotionKind::Feed;
    int line = 0; // 1-based line of the source file that programs this record
};

// Q = O + R V: the ball centre of a record for ball radius R, the point every method keeps.
inline Vec3 ballCentre(const ClRecord& record, double radius) {
    return record.tip + radius * record.axis.normalized();
}

struct Toolpath {
    std::string sourceFile; // for diagnostics ("blade.nc:120")
    SourceFormat format = SourceFormat::Gcode;
    std::vector<ClRecord> records;     // in program order, rapids included
    std::optional<double> toolRadius;  // mm, when the file states it (APT CUTTER/TLDATA)
    std::vector<std::string> warnings; // non-fatal findings of the reader, with file:line
};

} // namespace bladeaxis::toolpath

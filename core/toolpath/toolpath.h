#pragma once
// The toolpath model every reader produces and every stage consumes: ordered cutter-location
// (CL) records in the workpiece frame W, each with its provenance in the source file.
// Units: mm, rad, s (feeds are stored in mm/s).

#include "core/geometry/vec.h"
#include "core/kinematics/machine_model.h"

#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::toolpath {

enum class MotionKind { Rapid, Feed };

enum class SourceFormat { Gcode, Apt, Table };

// The machine axes a record was programmed with, or none: std::optional's interface held in
// the 40 bytes of the axes themselves. An absent value is marked by a NaN whose payload no
// reader or computation produces, so a record is 104 bytes rather than 112 (std::optional's
// flag is padded to 8): 40 MB on a five-million-block program, at every stage of a job.
class ProgrammedAxes {
  public:
    ProgrammedAxes() { markAbsent(); }
    ProgrammedAxes(std::nullopt_t) { markAbsent(); }
    ProgrammedAxes(const kinematics::MachineAxes& axes) : m_axes(axes) {}
    ProgrammedAxes& operator=(std::nullopt_t) {
        markAbsent();
        return *this;
    }
    ProgrammedAxes& operator=(const kinematics::MachineAxes& axes) {
        m_axes = axes;
        return *this;
    }

    bool has_value() const { return std::bit_cast<std::uint64_t>(m_axes.x) != kAbsent; }
    explicit operator bool() const { return has_value(); }
    const kinematics::MachineAxes& operator*() const { return m_axes; }
    kinematics::MachineAxes& operator*() { return m_axes; }
    const kinematics::MachineAxes* operator->() const { return &m_axes; }
    kinematics::MachineAxes* operator->() { return &m_axes; }
    const kinematics::MachineAxes& value() const {
        if (!has_value()) {
            throw std::bad_optional_access();
        }
        return m_axes;
    }
    void reset() { markAbsent(); }
    operator std::optional<kinematics::MachineAxes>() const {
        return has_value() ? std::optional(m_axes) : std::nullopt;
    }

  private:
    // A signalling NaN with a payload of its own: copies keep its bits, arithmetic never makes it.
    static constexpr std::uint64_t kAbsent = 0x7ff4'0000'b1ad'a5e5;
    void markAbsent() {
        m_axes = {};
        m_axes.x = std::bit_cast<double>(kAbsent);
    }

    kinematics::MachineAxes m_axes;
};

struct ClRecord {
    Vec3 tip = Vec3::Zero();   // O: tool tip (lowest point of the ball) in W, mm
    Vec3 axis = Vec3::UnitZ(); // V: unit tool axis from the tip towards the spindle, in W
    // The machine axes as programmed, when the record comes from an NC program (A unwrapped
    // as written: continuous programs keep their cumulative A).
    ProgrammedAxes axes;
    double feed = 0.0; // programmed tip feed in mm/s; 0 when unknown (rapids)
    MotionKind motion = MotionKind::Feed;
    int line = 0; // 1-based line of the source file that programs this record
};

// Q = O + R V: the ball centre of a record for ball radius R, the point every method keeps.
inline Vec3 ballCentre(const ClRecord& record, double radius) {
    return record.tip + radius * record.axis.normalized();
}

// A flat or bull-nose cutter the file states (its corner radius is not half its diameter).
// Re-orienting such a tool moves its contact point on the surface, so keeping its ball centre
// would not keep the surface: the job refuses it unless the job itself states a ball.
struct StatedCutter {
    double diameter = 0.0;     // mm
    double cornerRadius = 0.0; // mm
    int line = 0;              // 1-based line of the statement
    std::string statement;     // as the file writes it: "CUTTER/8,1", "(T1 D=8. CR=1.)"
};

struct Toolpath {
    std::string sourceFile; // for diagnostics ("blade.nc:120")
    SourceFormat format = SourceFormat::Gcode;
    std::vector<ClRecord> records;             // in program order, rapids included
    std::optional<double> toolRadius;          // mm, when the file states it (APT CUTTER/TLDATA)
    std::optional<StatedCutter> nonBallCutter; // the first flat or bull-nose cutter stated
    std::vector<std::string> warnings;         // non-fatal findings of the reader, with file:line
};

} // namespace bladeaxis::toolpath

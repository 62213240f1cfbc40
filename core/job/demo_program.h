#pragma once
// Synthetic blade programs: the built-in demo and `--generate`. The generator itself lives in
// core/blade; this turns a user request into a blade, a helical path and program text.

#include "core/base/error.h"
#include "core/kinematics/machine_model.h"

#include <cstdint>
#include <optional>
#include <string>

namespace bladeaxis::job {

inline constexpr const char* kDemoProgramName = "demo_blade.nc";

struct GenerateRequest {
    std::string profile = "naca-high-camber"; // naca-high-camber | naca-weak | symmetric | turbine
    std::string format = "gcode";             // gcode | apt
    std::optional<double> toolRadius;         // mm
    std::optional<double> revolutions;
    std::optional<double> pitch;            // mm of x per revolution
    std::optional<double> leadDeg;          // lead of the original CAM orientation, deg
    std::optional<double> tiltDeg;          // fixed B, deg
    std::optional<double> chordalTolerance; // mm
    std::uint64_t seed = 1;
};

struct GeneratedProgram {
    std::string text;  // the program in the requested format
    double toolRadius; // mm, the ball radius it was generated for
};

// A generated blade toolpath in the requested format. Deterministic for a given request.
Result<GeneratedProgram> generateProgram(const GenerateRequest& request,
                                         const kinematics::MachineModel& machine);

// The built-in demo: the default request (high-camber NACA blade) as G-code.
Result<GeneratedProgram> demoProgram(const kinematics::MachineModel& machine);

} // namespace bladeaxis::job

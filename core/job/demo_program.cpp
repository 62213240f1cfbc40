#include "core/job/demo_program.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/blade/presets.h"
#include "core/io/cl/apt.h"
#include "core/io/nc/gcode.h"
#include "core/io/program.h"

#include <cmath>

namespace bladeaxis::job {

namespace {

Result<blade::BladeSpec> bladeSpecFor(const std::string& profile) {
    blade::BladeSpec spec = blade::demoBladeSpec();
    if (profile == "naca-high-camber") {
        return spec;
    }
    if (profile == "naca-weak") {
        spec.profile = blade::NacaProfile{0.04, 0.40, 0.18}; // NACA 4418: concave near the TE only
    } else if (profile == "symmetric") {
        spec.profile = blade::NacaProfile{0.0, 0.40, 0.12}; // NACA 0012: no concave run
    } else if (profile == "turbine") {
        spec.profile = blade::TurbineProfile{};
    } else {
        return makeError(
            ErrorCode::InvalidArgument,
            "--profile: expected naca-high-camber, naca-weak, symmetric or turbine, got '" +
                profile + "'");
    }
    return spec;
}

// A fixed head (table_a, table_b) holds the tool at tilt 0, which the program must then state:
// the default 5 deg tilt wrote a program the same machine refused. A tilt asked of such a
// machine is refused rather than dropped.
Status fixedTilt(const GenerateRequest& request, const kinematics::MachineModel& machine,
                 blade::HelicalPathSpec& spec) {
    if (machine.hasB()) {
        return {};
    }
    if (request.tiltDeg && *request.tiltDeg != 0.0) {
        const std::string letter(1, machine.letter(kinematics::AxisId::B));
        return makeError(ErrorCode::InvalidArgument, "--tilt-deg: the machine (" + machine.name +
                                                         ") has a fixed head, its " + letter +
                                                         " is 0; expected no --tilt-deg "
                                                         "or 0, got " +
                                                         formatShortest(*request.tiltDeg));
    }
    spec.tiltB0 = 0.0;
    return {};
}

Result<blade::HelicalPathSpec> pathSpecFor(const GenerateRequest& request,
                                           const kinematics::MachineModel& machine) {
    blade::HelicalPathSpec spec = blade::demoPathSpec();
    if (request.toolRadius) {
        spec.toolRadius = *request.toolRadius;
    }
    if (request.revolutions) {
        if (*request.revolutions < 1.0 || *request.revolutions > 100000.0 ||
            std::floor(*request.revolutions) != *request.revolutions) {
            return makeError(ErrorCode::InvalidArgument,
                             "--revolutions: expected a whole number from 1 to 100000, got " +
                                 formatShortest(*request.revolutions));
        }
        spec.revolutions = static_cast<int>(*request.revolutions);
    }
    if (request.pitch) {
        spec.pitch = *request.pitch;
    }
    if (request.leadDeg) {
        spec.leadAngle = units::degToRad(*request.leadDeg);
    }
    if (request.tiltDeg) {
        spec.tiltB0 = units::degToRad(*request.tiltDeg);
    }
    if (auto fixed = fixedTilt(request, machine, spec); !fixed) {
        return std::unexpected(fixed.error());
    }
    if (request.chordalTolerance) {
        spec.chordalTolerance = *request.chordalTolerance;
    }
    spec.seed = request.seed;
    if (auto status = blade::validate(spec); !status) {
        Error error = status.error();
        error.code = ErrorCode::InvalidArgument;
        return std::unexpected(error);
    }
    return spec;
}

// The tilt is named and signed as the machine's program writes it (B, or A on a table-B one).
std::vector<std::string> headerComments(const GenerateRequest& request,
                                        const blade::HelicalPathSpec& path,
                                        const kinematics::MachineModel& machine) {
    const kinematics::ProgramWord tilt = machine.programWord(kinematics::AxisId::B);
    return {"BladeAxis synthetic blade program (" + request.profile + ", seed " +
                std::to_string(request.seed) + ")",
            "ball end R=" + formatTrimmed(path.toolRadius, 4) + " mm, " +
                machine.letter(kinematics::AxisId::B) + "=" +
                formatTrimmed(tilt.sign * units::radToDeg(path.tiltB0), 4) + " deg, lead " +
                formatTrimmed(units::radToDeg(path.leadAngle), 4) + " deg, " +
                std::to_string(path.revolutions) + " revolutions"};
}

} // namespace

Result<GeneratedProgram> generateProgram(const GenerateRequest& request,
                                         const kinematics::MachineModel& machine) {
    auto bladeSpec = bladeSpecFor(request.profile);
    if (!bladeSpec) {
        return std::unexpected(bladeSpec.error());
    }
    auto pathSpec = pathSpecFor(request, machine);
    if (!pathSpec) {
        return std::unexpected(pathSpec.error());
    }
    auto blade = blade::Blade::create(*bladeSpec);
    if (!blade) {
        return std::unexpected(blade.error());
    }
    auto generated = blade::generateHelicalPath(*blade, *pathSpec);
    if (!generated) {
        return std::unexpected(generated.error());
    }
    const auto comments = headerComments(request, *pathSpec, machine);
    if (request.format == "apt") {
        io::cl::AptEmitOptions options;
        options.toolRadius = pathSpec->toolRadius;
        options.comments = comments;
        toolpath::Toolpath path = generated->path; // CL data are in the program's frame
        io::toProgramFrame(path.records, machine);
        return GeneratedProgram{io::cl::emitApt(path, options), pathSpec->toolRadius};
    }
    if (request.format != "gcode") {
        return makeError(ErrorCode::InvalidArgument,
                         "--format: expected gcode or apt, got '" + request.format + "'");
    }
    io::nc::GcodeEmitOptions options;
    options.headerComments = comments;
    auto text = io::nc::emitGcode(generated->path, machine, options);
    if (!text) {
        return std::unexpected(text.error());
    }
    return GeneratedProgram{std::move(*text), pathSpec->toolRadius};
}

Result<GeneratedProgram> demoProgram(const kinematics::MachineModel& machine) {
    return generateProgram(GenerateRequest{}, machine);
}

} // namespace bladeaxis::job

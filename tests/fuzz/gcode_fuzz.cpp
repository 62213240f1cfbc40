// The G-code reader directly, in each dialect it reads (ISO with the angle unit given and
// detected and with both rules for numbers without a decimal point, Sinumerik, Heidenhain),
// and the minimal-diff writer on whatever it read, with A moved a little: the writer must give
// a program or a named refusal (a DC/ACP/ACN word the new A cannot keep), never anything else.
#include "core/io/nc/gcode_reader.h"
#include "core/io/nc/gcode_writer.h"
#include "core/kinematics/machine_model.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace {

using namespace bladeaxis;

void readAndRewrite(std::string_view text, const kinematics::MachineModel& machine,
                    const io::ReadOptions& options) {
    auto program = io::nc::parseGcode(text, "fuzz.nc", machine, options);
    fuzz::expectNoInternalError(program, "gcode");
    if (!program) {
        return;
    }
    std::vector<kinematics::MachineAxes> axes;
    axes.reserve(program->path.records.size());
    for (const toolpath::ClRecord& record : program->path.records) {
        kinematics::MachineAxes moved = *record.axes;
        moved.a += 0.001 * static_cast<double>(axes.size() % 3);
        axes.push_back(moved);
    }
    fuzz::expectNoInternalError(io::nc::rewriteGcode(*program, axes, machine), "gcode writer");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    static const kinematics::MachineModel wholeUnits = [] {
        kinematics::MachineModel units = kinematics::defaultBladeMachine();
        units.numbers.integerWords = kinematics::IntegerWords::Units;
        return units;
    }();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    io::ReadOptions degrees;
    degrees.angleUnit = io::AngleUnit::Degrees;
    io::ReadOptions sinumerik;
    sinumerik.dialect = io::NcDialect::Sinumerik;
    io::ReadOptions heidenhain;
    heidenhain.dialect = io::NcDialect::Heidenhain;
    fuzz::withoutExceptions("gcode", [&] {
        fuzz::expectNoInternalError(io::nc::parseGcode(text, "fuzz.nc", machine), "gcode");
        readAndRewrite(text, wholeUnits, degrees);
        readAndRewrite(text, machine, sinumerik);
        readAndRewrite(text, machine, heidenhain);
    });
    return 0;
}

// The G-code reader directly, with the angle unit given and with it detected, and with the
// machine's two rules for numbers without a decimal point.
#include "core/io/nc/gcode_reader.h"
#include "core/kinematics/machine_model.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    static const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    static const kinematics::MachineModel wholeUnits = [] {
        kinematics::MachineModel units = kinematics::defaultBladeMachine();
        units.numbers.integerWords = kinematics::IntegerWords::Units;
        return units;
    }();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    io::ReadOptions degrees;
    degrees.angleUnit = io::AngleUnit::Degrees;
    fuzz::withoutExceptions("gcode", [&] {
        fuzz::expectNoInternalError(io::nc::parseGcode(text, "fuzz.nc", machine), "gcode");
        fuzz::expectNoInternalError(io::nc::parseGcode(text, "fuzz.nc", wholeUnits, degrees),
                                    "gcode");
    });
    return 0;
}

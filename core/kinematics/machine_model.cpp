#include "core/kinematics/machine_model.h"

#include "core/base/units.h"

namespace bladeaxis::kinematics {

const char* axisName(AxisId axis) {
    static constexpr std::array<const char*, 5> kNames{"X", "Y", "Z", "A", "B"};
    return kNames[static_cast<int>(axis)];
}

double MachineAxes::operator[](AxisId axis) const {
    switch (axis) {
    case AxisId::X:
        return x;
    case AxisId::Y:
        return y;
    case AxisId::Z:
        return z;
    case AxisId::A:
        return a;
    case AxisId::B:
        return b;
    }
    return 0.0;
}

double& MachineAxes::operator[](AxisId axis) {
    switch (axis) {
    case AxisId::X:
        return x;
    case AxisId::Y:
        return y;
    case AxisId::Z:
        return z;
    case AxisId::A:
        return a;
    case AxisId::B:
        return b;
    }
    return x;
}

MachineModel defaultBladeMachine() {
    using units::degToRad;
    MachineModel machine;
    machine.name = "Generic blade machine (rotary table A about X, pivoting head B about Y)";
    // Spec §8.3 default set: linear 500 mm/s, 3000 mm/s^2, 30000 mm/s^3; A 360 deg/s,
    // 1800 deg/s^2, 18000 deg/s^3. Travels after the reference machine's strokes (W4).
    const AxisLimits linear{true, 0.0, 0.0, 500.0, 3000.0, 30000.0, 0.0};
    machine.limit(AxisId::X) = linear;
    machine.limit(AxisId::X).min = -1400.0;
    machine.limit(AxisId::X).max = 1400.0;
    machine.limit(AxisId::Y) = linear;
    machine.limit(AxisId::Y).min = -330.0;
    machine.limit(AxisId::Y).max = 330.0;
    machine.limit(AxisId::Z) = linear;
    machine.limit(AxisId::Z).min = -300.0;
    machine.limit(AxisId::Z).max = 500.0;
    machine.limit(AxisId::A) = {
        false, 0.0, 0.0, degToRad(360.0), degToRad(1800.0), degToRad(18000.0), degToRad(0.005)};
    machine.limit(AxisId::B) = {
        true, degToRad(-87.0), degToRad(87.0), degToRad(90.0), degToRad(900.0), degToRad(9000.0),
        0.0};
    machine.aMode = RotaryMode::Continuous;
    return machine;
}

} // namespace bladeaxis::kinematics

#include "core/kinematics/machine_model.h"

#include "core/base/units.h"

namespace bladeaxis::kinematics {

const char* axisName(AxisId axis) {
    static constexpr std::array<const char*, 5> kNames{"X", "Y", "Z", "A", "B"};
    return kNames[static_cast<int>(axis)];
}

const char* plannerName(Planner planner) {
    return planner == Planner::BlockByBlock ? "block-by-block" : "look-ahead";
}

std::optional<Planner> plannerNamed(std::string_view name) {
    if (name == "look-ahead") {
        return Planner::LookAhead;
    }
    if (name == "block-by-block") {
        return Planner::BlockByBlock;
    }
    return std::nullopt;
}

const char* layoutName(Layout layout) {
    switch (layout) {
    case Layout::TableAHeadB:
        return "table_a_head_b";
    case Layout::TableA:
        return "table_a";
    case Layout::TableBHeadA:
        return "table_b_head_a";
    case Layout::TableB:
        return "table_b";
    }
    return "table_a_head_b";
}

ProgramWord MachineModel::programWord(AxisId axis) const {
    const auto role = static_cast<std::size_t>(axis);
    if (!turnsAboutY()) {
        return {role, 1.0};
    }
    // Engine X Y Z A B <- program Y, -X, Z, B, -A.
    static constexpr std::array<ProgramWord, 5> kTableB{
        {{1, 1.0}, {0, -1.0}, {2, 1.0}, {4, 1.0}, {3, -1.0}}};
    return kTableB[role];
}

AxisId MachineModel::axisOfWord(std::size_t index) const {
    for (const AxisId axis : kAllAxes) {
        if (programWord(axis).index == index) {
            return axis;
        }
    }
    return AxisId::X;
}

MachineAxes MachineModel::fromProgramValues(const std::array<double, 5>& values) const {
    MachineAxes axes;
    for (const AxisId axis : kAllAxes) {
        const ProgramWord word = programWord(axis);
        axes[axis] = word.sign * values[word.index];
    }
    return axes;
}

std::array<double, 5> MachineModel::programValues(const MachineAxes& axes) const {
    std::array<double, 5> values{};
    for (const AxisId axis : kAllAxes) {
        const ProgramWord word = programWord(axis);
        values[word.index] = word.sign * axes[axis];
    }
    return values;
}

// A quarter turn about Z: (x, y, z) -> (y, -x, z) puts the machine's Y on the engine's x.
Vec3 MachineModel::toEngineFrame(const Vec3& v) const {
    return turnsAboutY() ? Vec3(v.y(), -v.x(), v.z()) : v;
}

Mat3 MachineModel::engineFrameRotation() const {
    Mat3 rotation;
    for (int column = 0; column < 3; ++column) {
        rotation.col(column) = toEngineFrame(Mat3::Identity().col(column));
    }
    return rotation;
}

Vec3 MachineModel::toProgramFrame(const Vec3& v) const {
    return turnsAboutY() ? Vec3(-v.y(), v.x(), v.z()) : v;
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

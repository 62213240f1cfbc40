#pragma once
// The machine: a rotary table carrying the blade plus a spindle head that tilts or is fixed.
// The engine works on one chain, a rotary table A about X with a head B tilting about Y
// (spec §6.3, the Starrag LX451 kind of blade machine); a machine whose table turns about Y
// (B) is the same chain seen from a frame turned a quarter turn about Z, so its words are
// mapped at the program's boundary (MachineModel::programWord). Machine descriptions are data
// files (resources/machines/*.json, schema in docs/machine-file.md) loaded by machine_file.h.
// Units: mm, rad, s.

#include "core/geometry/vec.h"

#include <array>
#include <optional>
#include <string>

namespace bladeaxis::kinematics {

// An axis of the engine's chain, by its role: x along the table's axis, A the rotary table, B
// the head's tilt. On a table-A machine these are also the program's letters.
enum class AxisId { X = 0, Y = 1, Z = 2, A = 3, B = 4 };
constexpr std::array<AxisId, 5> kAllAxes{AxisId::X, AxisId::Y, AxisId::Z, AxisId::A, AxisId::B};
const char* axisName(AxisId axis);
inline bool isRotary(AxisId axis) {
    return axis == AxisId::A || axis == AxisId::B;
}

// Programmed machine axis values: linear in mm, rotary in rad (as the controller sees them,
// after the machine's sign conventions).
struct MachineAxes {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    double a = 0.0;
    double b = 0.0;

  private:
    template <class Self>
    static auto& member(Self& self, AxisId axis) {
        switch (axis) {
        case AxisId::X:
            return self.x;
        case AxisId::Y:
            return self.y;
        case AxisId::Z:
            return self.z;
        case AxisId::A:
            return self.a;
        case AxisId::B:
            return self.b;
        }
        return self.x;
    }

  public:
    // Inline: the analysis reads one axis of millions of records through it.
    double operator[](AxisId axis) const { return member(*this, axis); }
    double& operator[](AxisId axis) { return member(*this, axis); }
};

// Per-axis limits. Linear axes: mm, mm/s, mm/s^2, mm/s^3. Rotary axes: rad, rad/s, ...
struct AxisLimits {
    bool hasTravel = false; // false: unlimited (continuous rotary axis)
    double min = 0.0;
    double max = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
    double jerk = 0.0;
    double backlash = 0.0;
};

enum class RotaryMode {
    Continuous, // A is programmed as a cumulative angle (may exceed 360 deg)
    Modulo,     // A is programmed in [0, 360) deg and the controller takes the shortest way
};

// Geometry of the table-A / head-B chain. The workpiece frame W has its origin on the A axis
// and x along it; the tool axis is +Z at B = 0.
struct TableAHeadB {
    double pivotLength = 0.0; // mm from the B pivot to the tool tip; 0 for tip-programmed (TCPM)
    Vec3 tableOffset = Vec3::Zero(); // mm, c_table: A axis position in machine coordinates
    Vec3 headOffset = Vec3::Zero();  // mm, c_head: offset of the programmed point from the pivot
    int aSign = 1; // +1 when +A turns the workpiece right-handed about +X; -1 per ISO 841 flip
    int bSign = 1; // +1 when +B tilts the tool right-handed about +Y
    // Tool-tip programming with the control's transformation on (Sinumerik TRAORI, Heidenhain
    // M128 / FUNCTION TCPM): X Y Z are the tool tip in the workpiece frame W, and the control
    // moves the machine's linear axes for the table and head. Set by the program, not the file.
    bool tipInWorkpiece = false;
};

// How the control reads an axis word without a decimal point ("X1000"). Fanuc-style controls
// take it as a count of least input increments (1.000 mm at 0.001 mm); others, and Fanuc in
// pocket-calculator mode, as whole millimetres or degrees.
enum class IntegerWords {
    RefuseMixed, // whole units, but a program that mixes both styles is refused (the default:
                 // mixing is the sign of a post written for the other rule)
    Units,       // whole mm / inch / deg
    Increments,  // least input increments
};

struct NumberRules {
    IntegerWords integerWords = IntegerWords::RefuseMixed;
    double incrementMm = 0.001;    // least input increment of linear words in G21
    double incrementInch = 0.0001; // in G20
    double incrementDeg = 0.001;   // of rotary words
};

// What F means in a G94 block of an ISO program without tool-tip programming.
enum class FeedMeaning {
    Path,         // the programmed point's speed along its path (tool-tip controls; the default)
    CombinedAxes, // Fanuc-style: F along the vector of all axis moves, mm and degrees together;
                  // a block lasts sqrt(dX^2 + dY^2 + dZ^2 + dA^2 + dB^2) / F
};

// Which rotary axis the table turns about, and whether the head tilts.
enum class Layout {
    TableAHeadB, // table A about X, head B about Y ("table_a_head_b")
    TableA,      // table A about X, fixed head ("table_a")
    TableBHeadA, // table B about Y, head A about X ("table_b_head_a")
    TableB,      // table B about Y, fixed head ("table_b")
};

// The machine file's "type" of a layout ("table_b_head_a").
const char* layoutName(Layout layout);

// The program's word for an axis of the engine's chain: its index in X Y Z A B order and the
// sign from the program's value to the engine's.
struct ProgramWord {
    std::size_t index = 0;
    double sign = 1.0;
};

// The letters X Y Z A B in the order of program words.
inline constexpr std::array<char, 5> kProgramLetters{'X', 'Y', 'Z', 'A', 'B'};

struct MachineModel {
    std::string name;
    std::string sourceFile; // where it was loaded from; empty for built-in models
    TableAHeadB chain;      // in the engine's frame (offsets turned for a table-B layout)
    Layout layout = Layout::TableAHeadB;
    std::array<AxisLimits, 5> limits{};
    RotaryMode aMode = RotaryMode::Continuous;
    NumberRules numbers; // how its control reads numbers without a decimal point
    FeedMeaning feedMeaning = FeedMeaning::Path;

    const AxisLimits& limit(AxisId axis) const { return limits[static_cast<int>(axis)]; }
    AxisLimits& limit(AxisId axis) { return limits[static_cast<int>(axis)]; }

    // The program's word for an engine axis. Table A: the identity. Table B: the engine's x is
    // the machine's Y, its y the machine's -X, the table is B and the head's A tilts the
    // engine's B the other way (a right-handed turn about +X is one about the engine's -y).
    ProgramWord programWord(AxisId axis) const;
    char letter(AxisId axis) const { return kProgramLetters[programWord(axis).index]; }
    // The engine axis a program word (index in X Y Z A B order) drives.
    AxisId axisOfWord(std::size_t index) const;
    // Program values (X Y Z A B order, mm / rad as programmed) to engine axes and back.
    MachineAxes fromProgramValues(const std::array<double, 5>& values) const;
    std::array<double, 5> programValues(const MachineAxes& axes) const;
    // A point or direction of the program's workpiece frame (CL data, CAD models: the table's
    // axis along X for table A, along Y for table B) in the engine's frame, and back.
    Vec3 toEngineFrame(const Vec3& v) const;
    Vec3 toProgramFrame(const Vec3& v) const;
    // The rotation of toEngineFrame, for rigid placements (a CAD model); its transpose turns back.
    Mat3 engineFrameRotation() const;
    bool turnsAboutY() const { return layout == Layout::TableBHeadA || layout == Layout::TableB; }
    // false for a fixed head (machine file types "table_a", "table_b"): the tilt is 0, a program
    // that tilts it is refused, and the tilt's limits are placeholders that never bind.
    bool hasB() const { return layout == Layout::TableAHeadB || layout == Layout::TableBHeadA; }
};

// The built-in default blade machine (the same values as resources/machines/blade_ab.json):
// spec §8.3 limits, continuous A, tip-programmed.
MachineModel defaultBladeMachine();

} // namespace bladeaxis::kinematics

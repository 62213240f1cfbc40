#pragma once
// The machine: a rotary table A about X plus a pivoting spindle head B about Y (spec §6.3,
// the Starrag LX451 kind of blade machine). Machine descriptions are data files
// (resources/machines/*.json, schema in docs/machine-file.md) loaded by machine_file.h.
// Units: mm, rad, s.

#include "core/geometry/vec.h"

#include <array>
#include <string>

namespace bladeaxis::kinematics {

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

    double operator[](AxisId axis) const;
    double& operator[](AxisId axis);
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

struct MachineModel {
    std::string name;
    std::string sourceFile; // where it was loaded from; empty for built-in models
    TableAHeadB chain;
    // false for a fixed head (machine file type "table_a"): B is 0, a program that tilts it is
    // refused, and the B limits are placeholders that never bind.
    bool hasB = true;
    std::array<AxisLimits, 5> limits{};
    RotaryMode aMode = RotaryMode::Continuous;
    NumberRules numbers; // how its control reads numbers without a decimal point
    FeedMeaning feedMeaning = FeedMeaning::Path;

    const AxisLimits& limit(AxisId axis) const { return limits[static_cast<int>(axis)]; }
    AxisLimits& limit(AxisId axis) { return limits[static_cast<int>(axis)]; }
};

// The built-in default blade machine (the same values as resources/machines/blade_ab.json):
// spec §8.3 limits, continuous A, tip-programmed.
MachineModel defaultBladeMachine();

} // namespace bladeaxis::kinematics

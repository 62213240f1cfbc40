#pragma once
// Is the program a four-axis helical blade pass that BladeAxis may re-schedule? A program it does
// not understand is refused before anything is written, never rewritten: a five-axis program's
// tool axis turned into a four-axis channel would come out tilted the wrong way.
//
// Two conditions, each refused with its amount, the first offending record's file:line and what
// the user can do:
// - the tilt B (the angle of the tool axis to the plane normal to the rotary axis, asin(V . a))
//   is constant along the cutting pass within a tolerance; noise within it is snapped to the
//   median (keeping every ball centre) and reported;
// - the CAM orientation lies inside the feasible S-theta channel, or within a stated angle of it
//   (a program for another machine or kinematics, or a tool axis from below the surface, lies
//   far outside).

#include "core/base/error.h"
#include "core/base/units.h"
#include "core/scheduling/schedule.h"
#include "core/toolpath/toolpath.h"

#include <span>
#include <string>

namespace bladeaxis::job {

struct ProgramCheckOptions {
    // Largest deviation of B from its median along the pass, rad (`--b-tolerance-deg`).
    double tiltToleranceRad = units::degToRad(0.01);
    // Largest distance of the CAM orientation outside the raw channel, rad
    // (`--channel-tolerance-deg`). CAM output with a fixed lead angle lies inside the channel
    // (it is the channel's reason to exist); a few degrees outside are collision margins and
    // rounding; a turbine section with a 30 deg lead lies 22 deg outside its channel on the
    // synthetic family, a tool axis from below the surface or another machine's program 90 deg and
    // more.
    double channelToleranceRad = units::degToRad(30.0);
};

// The program's words of the rotary table and of the head's tilt, for the messages: A and B on
// a table-A machine, B and A on a table-B one (MachineModel::letter), whose head's A tilts the
// other way (tiltSign -1: the program's value of a tilt is tiltSign times the engine's).
struct RotaryLetters {
    char table = 'A';
    char tilt = 'B';
    double tiltSign = 1.0;
};

struct TiltCheck {
    double medianRad = 0.0;         // the tilt the pass is re-scheduled with
    double largestDeviationRad = 0; // max |B - median| over the pass
    std::size_t snappedRecords = 0; // records whose B was moved to the median
};

// The tilt of one tool axis: asin(V . a / |V|), a = +x (the rotary axis), rad.
double tiltOf(const Vec3& axis);

// Refuses (ErrorCode::Geometry) a pass whose B deviates from its median by more than the
// tolerance, naming the first such record. Does not change the records.
Result<TiltCheck> checkConstantTilt(std::span<const toolpath::ClRecord> pass,
                                    const std::string& file, const ProgramCheckOptions& options,
                                    RotaryLetters letters);

// Tilt deviations up to this are the rounding of the file's numbers (a unit vector written at six
// decimals), not noise worth a warning, rad.
inline constexpr double kReportedTiltDeviationRad = 1e-5;

// Turns every tool axis of the pass to the tilt `tiltRad` about the rotary axis' plane, keeping
// its in-plane angle and its ball centre O + R V (the tip moves by R times the change of V).
// Returns how many records deviated by more than kReportedTiltDeviationRad. The programmed
// machine axes (ClRecord::axes) stay as read: they describe the original program.
std::size_t snapTilt(std::span<toolpath::ClRecord> pass, double tiltRad, double toolRadius);

// The warning that reports a snap, in degrees; empty when nothing was snapped.
std::string describeSnap(const TiltCheck& tilt, const std::string& file, RotaryLetters letters);

// The smallest turn of the ball centres about the rotary axis over the cutting pass that makes
// it a helical pass, rad. A helical blade pass turns a whole revolution per layer; rotary words
// in radians read as degrees (or a program for a machine without the rotary axis) turn the
// centres by a few degrees at most.
inline constexpr double kMinimumHelicalTurnRad = units::kPi;

// How the program's rotary words were read, for the advice of a refusal: CL data and point
// tables have none (vectors); G-code's unit comes from its header or values, or was given.
enum class AngleWordsRead { NoAngleWords, Inferred, GivenDegrees, GivenRadians };

// Refuses (ErrorCode::Geometry) a pass whose ball centres turn less than kMinimumHelicalTurnRad
// about the rotary axis (x), naming its first and last record; the advice names radians only
// where the unit may be the cause.
Status checkHelical(std::span<const toolpath::ClRecord> pass, double toolRadius,
                    const std::string& file, RotaryLetters letters, AngleWordsRead angles);

// Refuses (ErrorCode::Geometry) a schedule whose CAM orientation (the input's theta) lies more
// than the tolerance outside the raw channel of its layer, naming the first such record.
Status checkOrientationInChannel(const scheduling::ScheduleResult& schedule,
                                 std::span<const toolpath::ClRecord> pass, const std::string& file,
                                 const ProgramCheckOptions& options, RotaryLetters letters);

} // namespace bladeaxis::job

#pragma once
// The samples of a posted program that carry motion (docs/figures.md). Posts and CAM systems
// split moves at tolerance boundaries and write chords of a few micrometres on the straight
// move between two CL points. The controller moves along the same straight line with or
// without such a point, but a spline through it must bend within micrometres, and its
// acceleration there measures the split, not the tool orientation: one 2 um chord every few
// points raised a peak by 60-80 %. So a sample is a knot of the derivative spline unless it is
// both close to the previous knot and on the straight move past it.

#include "core/analysis/axis_profile.h"
#include "core/kinematics/machine_model.h"

#include <cstddef>
#include <span>
#include <vector>

namespace bladeaxis::analysis {

struct MotionKnotTolerances {
    // A chord shorter than this fraction of the program's median chord is short. A tenth is far
    // below the chord lengths a chordal tolerance gives on one blade pass (the chord grows with
    // the square root of the curvature radius: a tenth of the median is a radius 100 times
    // tighter than the typical one) and far above the micrometre chords of a split move.
    double shortChordFraction = 0.1;
    // A short-chord sample within these of the straight move (in machine axes, interpolated
    // linearly in the path parameter) from the previous knot to the next sample adds no motion
    // a controller follows: the tightest tolerances a finishing program is made to (5 um
    // chordal, 0.01 deg of orientation), which is also what a control's compressor or corner
    // blending merges. A split point of a smoothly curved schedule lies off the chord by
    // t (1 - t) h^2 q'' / 2, micro-radians for a 5 um split of a 0.4 mm chord.
    double linearMm = 5e-3;
    double rotaryRad = 1.7453292519943295e-4; // 0.01 deg
};

// Ascending indices into `s` (the samples, s strictly increasing; sampleRecord maps a sample to
// its record in `axes`), always with the first and the last sample. A sample whose chord is
// short but which moves an axis off the straight move (a rotation at an almost fixed point, a
// corner) stays a knot: that motion is real and the figures must show it.
std::vector<std::size_t> motionKnots(std::span<const double> s,
                                     std::span<const kinematics::MachineAxes> axes,
                                     std::span<const RecordIndex> sampleRecord,
                                     const MotionKnotTolerances& tolerances = {});

// The median of the chords s[i+1] - s[i] (0 for fewer than 2 samples). O(n).
double medianChord(std::span<const double> s);

} // namespace bladeaxis::analysis

#pragma once
// Spec §1.5: robust discrete tangents over a minimum chord length, and the signed turning.
// Points are in the feed-oriented plane frame (feed counter-clockwise), so tau > 0 = convex.

#include "core/base/default_init.h"
#include "core/base/error.h"
#include "core/geometry/vec.h"

#include <span>
#include <vector>

namespace bladeaxis::scheduling {

struct TangentField {
    double chordLengthMm = 0.0;             // l_t actually used
    DefaultInitVector<double> forwardAngle; // ang(e+_i), unwrapped along the whole path, rad
    DefaultInitVector<double> turning;      // tau_i = wrap(ang(e+) - ang(e-)), rad, > 0 convex
    DefaultInitVector<double> curvature;    // 2 tau_i / (|e+| + |e-|), 1/mm
};

// l_t = max(minChordMm, medianFactor * median chord). Where no chord of length l_t exists
// (path ends), the farthest point is used, and at the very ends the other-side chord.
// Fails (Geometry) when all points coincide in projection. The chords are found on the
// context's threads (core/base/execution.h), with the same result as on one.
Result<TangentField> computeTangents(std::span<const Vec2> points, double minChordMm,
                                     double medianFactor);

// computeTangents in its two steps, so that other serial work can run beside the second: the
// field with each forwardAngle wrapped to (-pi, pi], then those angles unwrapped along the
// path. The unwrap is one chain through the path (each angle is taken near the previous one,
// whose rounding it inherits), so it runs on one thread.
Result<TangentField> computeWrappedTangents(std::span<const Vec2> points, double minChordMm,
                                            double medianFactor);
void unwrapForwardAngles(TangentField& field);

} // namespace bladeaxis::scheduling

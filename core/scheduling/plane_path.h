#pragma once
// Spec §1.2-1.4: cutter centres merged and projected onto the layer plane, in a plane frame
// oriented so that the feed goes counter-clockwise (angles grow in the feed sense), 3-D arc
// length S, the original in-plane axis angles and the fixed tilt B0.

#include "core/base/default_init.h"
#include "core/base/error.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule_samples.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::scheduling {

struct PlanePath {
    std::vector<Vec2> points;                // q_i in the plane frame (r = +z, p = w x r), mm
    DefaultInitVector<double> arcLength;     // S from the start, 3-D, strictly increasing, mm
    DefaultInitVector<double> originalAngle; // ang(P_perp V_i), wrapped to (-pi, pi], rad:
                                             // made by addOriginalAngles
    // Input index of each distinct sample: 32 bits, half a size_t's 8 bytes per sample, as an
    // input has fewer than 2^32 samples (preparePlanePath refuses more).
    DefaultInitVector<std::uint32_t> firstInput;
    double tiltB0 = 0.0;   // asin(V . a), rad
    int traversalSign = 1; // w . a (+1: feed turns about +x), spec §1.3
    std::vector<std::string> warnings;
};

// Fails (Geometry / InvalidArgument) on empty or mismatched input, non-finite values, zero
// axes, axes along the rotary axis, or fewer than 3 distinct centres. The per-point work runs
// on the context's threads (core/base/execution.h), with the same result as on one.
Result<PlanePath> preparePlanePath(std::span<const Vec3> centres, std::span<const Vec3> axes);
// The same for samples read where the caller keeps them (bit for bit what arrays would give).
Result<PlanePath> preparePlanePath(const ScheduleSamples& samples);

// The original angles of a path's distinct samples, from the input's axes (the ones the path
// was made from). Separate from preparePlanePath because only the layer problems read them:
// the scheduling makes them once the tangents and curvature are gone (8 bytes per sample fewer
// where its memory peaked).
void addOriginalAngles(PlanePath& path, std::span<const Vec3> axes);
void addOriginalAngles(PlanePath& path, const Vec3Run& axes);

// ang(P_perp v) of spec §1.3 for a traversal sign w . a: atan2(v . p, v . r), r = +z.
double planeAngle(const Vec3& v, int traversalSign);

// Unit tool axis whose in-plane angle is `angle` and whose axial component is sin(tiltB0)
// (spec §6.1: V = (sin B0, sin A cos B0, cos A cos B0) with A = -traversalSign * angle).
Vec3 axisFromPlaneAngle(double angle, double tiltB0, int traversalSign);

} // namespace bladeaxis::scheduling

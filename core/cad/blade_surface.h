#pragma once
// The synthetic blade (core/blade) as a CAD surface: one bicubic B-spline face interpolating the
// blade sections at evenly spaced stations x = const.
//
// u runs along the section (counter-clockwise in (y, z), closed, seam at the sharpest vertex,
// i.e. the closed trailing edge of a NACA section, where the surface may have a crease), v runs
// along the span (+x). With that orientation the face normal Su x Sv points out of the blade.
// Every section of a blade has the same vertex count and vertex i corresponds across the span
// (analytic profiles are scaled and turned copies, tables are resampled to a common count), so
// the sections form a regular grid of points that the surface passes through exactly.

#include "core/base/error.h"
#include "core/blade/blade.h"
#include "core/cad/cad_shape.h"

namespace bladeaxis::cad {

struct BladeSurfaceOptions {
    // Number of stations over the span; 0 = one every `stationSpacing` mm (at least 4, the
    // minimum for a cubic).
    int stations = 0;
    double stationSpacing = 1.0; // mm
};

// Errors: InvalidArgument (options), Geometry (sections of unequal size, degenerate span or an
// interpolation OpenCASCADE cannot build).
Result<CadShape> makeBladeSurface(const blade::Blade& blade,
                                  const BladeSurfaceOptions& options = {});

} // namespace bladeaxis::cad

#pragma once
// Sections of a CAD shape by the planes x = const, i.e. perpendicular to the rotary axis A (the
// section planes of the synthetic blades, spec §1.1 and §10.4). Faces bounded by the natural
// boundary of a B-spline or Bezier surface are intersected with the plane directly
// (GeomAPI_IntSS, about 17 ms on the demo blade); all other faces (planes, trimmed surfaces) go
// through OpenCASCADE's boolean section (BRepAlgoAPI_Section), which trims by the face
// boundaries but costs about a second per plane on a blade surface of 800 x 21 poles. The
// curves are returned as polylines in mm, chained end to end into as few pieces as possible.

#include "core/base/error.h"
#include "core/cad/cad_shape.h"
#include "core/geometry/vec.h"

#include <span>
#include <vector>

namespace bladeaxis::cad {

struct Polyline3 {
    // A closed polyline does not repeat its first point and runs counter-clockwise in (y, z).
    std::vector<Vec3> points;
    bool closed = false;
};

struct SectionOptions {
    double deflection = 0.002;       // mm, largest chord sag of the polylines from the curves
    double angularDeflection = 0.05; // rad, largest turn between consecutive chords
    bool booleanOnly = false;        // every face through BRepAlgoAPI_Section (the reference)
};

// An empty list when the plane misses the shape. Errors: InvalidArgument (null shape, options,
// non-finite x), Geometry (OpenCASCADE could not intersect).
Result<std::vector<Polyline3>> sectionAtX(const CadShape& shape, double x,
                                          const SectionOptions& options = {});

// The sections at every x, in order. The shape is shared read-only between as many workers as
// the context's thread count (core/base/execution.h); each plane is an independent boolean
// operation.
Result<std::vector<std::vector<Polyline3>>>
sectionsAtX(const CadShape& shape, std::span<const double> xs, const SectionOptions& options = {});

} // namespace bladeaxis::cad

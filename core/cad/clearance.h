#pragma once
// Clearance of the tool against the blade at every CL point of a program: the ball (gouge: the
// ball centre closer to the surface than R), the shank and the holder (collision: the solid
// reaches into the surface), each as a distance in mm per record, the minimum per layer, and
// the violations with the record's source line.
//
// Method: the blade's triangle mesh is sampled densely (surface_samples.h) and each tool part
// is queried with its exact signed distance through the bounding-volume hierarchy. This is
// chosen over BRepExtrema_DistShapeShape, which builds a tool shape and runs an iterative
// extremum search per CL point (milliseconds each; a blade program has 10^5 points), and over
// exact point-triangle distances, which have no closed form for cones and cylinders. The error
// is bounded by the mesh deflection plus the sampling coverage and is second order at grazing
// contacts. The tool is checked at every CL record it is given (rapids included), not swept
// between them (CL points of finish paths are dense: the chordal tolerance is a few microns).
// The job gives it the cutting pass only (job/cad_check.h says why).
//
// Sign conventions: ball = dist(Q, surface) - R (negative = gouge depth); shank and holder =
// signed distance from the part to the nearest surface sample (negative = penetration). A ball
// centre deep inside a part thicker than 2R would not be seen as a gouge: the check assumes an
// open surface or thin walls, as blades are.

#include "core/base/error.h"
#include "core/cad/surface_samples.h"
#include "core/cad/tool_geometry.h"
#include "core/toolpath/toolpath.h"

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::cad {

struct ClearanceOptions {
    double gougeTolerance = 0.01;  // mm; a ball clearance below -tolerance is a gouge
    double minimumClearance = 0.0; // mm; shank or holder closer than this is a collision
    // Distances are exact up to this limit and reported as the limit beyond it: the search then
    // prunes everything farther away (4 us per CL point at 5 mm, 100 us unlimited, on the demo
    // profile). Collisions and near misses are always exact.
    double searchLimit = 5.0; // mm, > 0 (infinity = exact everywhere)
    // Inclusive record ranges per layer; empty = one layer per revolution of the ball centre
    // about the rotary axis x, counted from the first record.
    std::vector<std::pair<std::size_t, std::size_t>> layers;
};

struct RecordClearance {
    double ball = 0.0;
    double shank = 0.0;
    double holder = 0.0;
};

// The smallest clearance of each tool part over `records` (+infinity when empty).
RecordClearance minimumOf(std::span<const RecordClearance> records);

enum class ClearanceKind { Gouge, ShankCollision, HolderCollision };

const char* toString(ClearanceKind kind);

struct ClearanceIssue {
    std::size_t record = 0;
    int line = 0; // source line of the record (0 when unknown)
    ClearanceKind kind = ClearanceKind::Gouge;
    double depth = 0.0; // mm below the allowed clearance, > 0
};

struct LayerClearance {
    std::size_t first = 0, last = 0; // inclusive record range
    RecordClearance minimum;         // per part, over the layer
    std::size_t issues = 0;
};

struct ClearanceReport {
    std::vector<RecordClearance> records;
    std::vector<LayerClearance> layers;
    std::vector<ClearanceIssue> issues; // in record order
    double samplingError = 0.0;         // the samples' coverage radius, mm
};

// "blade.nc:120: shank collision 0.420 mm deep (record 117)".
std::string describe(const ClearanceIssue& issue, const std::string& sourceFile);

// Errors: InvalidArgument (tool, options, layer ranges), Geometry (a non-finite CL record or a
// zero tool axis).
Result<ClearanceReport> checkClearance(const SurfaceSamples& blade, const toolpath::Toolpath& path,
                                       const ToolGeometry& tool,
                                       const ClearanceOptions& options = {});

} // namespace bladeaxis::cad

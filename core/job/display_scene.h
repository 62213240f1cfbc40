#pragma once
// What the 3-D view and the section view draw, computed once from a job's result so that the GUI
// only turns arrays into pictures: the blade surface (from the CAD when the job has it, otherwise
// reconstructed from the toolpath's contact points), the toolpath per layer with its original and
// re-scheduled tool axes and A-axis speeds, and the blade section of every layer. Large programs
// are decimated to what a view can draw interactively. Units: mm, rad, s, W frame.

#include "core/analysis/axis_profile.h"
#include "core/cad/cad_shape.h"
#include "core/cad/sections.h"
#include "core/cad/triangle_mesh.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"
#include "core/toolpath/toolpath.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::job {

struct JobResult;

enum class SurfaceSource {
    None,          // nothing to draw (no radius and too few points)
    Cad,           // tessellated blade CAD (or the demo blade's own surface)
    Reconstructed, // contact points of the toolpath, consecutive revolutions joined
};

const char* toString(SurfaceSource source);

struct DisplayLimits {
    std::size_t maxPathPoints = 200'000;     // drawn toolpath points
    std::size_t maxGlyphs = 2'000;           // tool-axis glyphs of each kind
    std::size_t maxGlyphsPerLayer = 48;      // fewer on short programs: readable, not a brush
    std::size_t maxSurfaceVertices = 60'000; // of a reconstructed surface
    double cadDeflection = 0.05;             // mm, chord sag of the CAD tessellation
};

struct DisplayLayer {
    std::size_t firstPoint = 0, lastPoint = 0;   // drawn points, inclusive
    std::size_t firstRecord = 0, lastRecord = 0; // records of the cutting pass, inclusive
    double sectionX = 0.0;                       // mm, plane x = sectionX of the section
    std::vector<cad::Polyline3> section;         // the blade in that plane, W
};

struct DisplayScene {
    cad::TriangleMesh surface;
    std::vector<Vec3> surfaceNormals; // per surface vertex, unit, outwards
    SurfaceSource surfaceSource = SurfaceSource::None;
    std::string surfaceName; // the CAD file, "demo blade surface" or "contact points"

    // The drawn points of the cutting pass, in feed order; every one has the entries below.
    std::vector<std::size_t> record;       // index into the cutting pass
    std::vector<Vec3> tips;                // of the program shown (re-scheduled when present)
    std::vector<Vec3> centres;             // ball centres (the same before and after)
    std::vector<Vec3> originalAxes;        // unit
    std::vector<Vec3> rescheduledAxes;     // unit; empty without a schedule
    std::vector<std::size_t> layer;        // index into layers
    std::vector<double> aSpeedOriginal;    // |dA/dt|, rad/s; empty when not analysed
    std::vector<double> aSpeedRescheduled; // rad/s; empty without a re-scheduled analysis
    std::vector<std::size_t> glyphPoints;  // drawn points that carry a tool-axis glyph

    std::vector<DisplayLayer> layers;
    double toolRadius = 0.0;     // mm; 0 when unknown
    std::size_t passRecords = 0; // before decimation
    std::vector<std::string> warnings;

    bool empty() const { return record.empty(); }
    bool hasRescheduled() const { return !rescheduledAxes.empty(); }
};

// Everything buildDisplayScene reads; pointers may be null when the job has no such part.
struct DisplaySceneInput {
    std::span<const toolpath::ClRecord> pass; // the cutting pass as read
    double toolRadius = 0.0;                  // mm; 0 when unknown (no contact offset)
    const cad::CadShape* blade = nullptr;
    std::string bladeName;
    const scheduling::ScheduleResult* schedule = nullptr; // indices are pass records
    const analysis::AxisProfile* originalProfile = nullptr;
    const analysis::AxisProfile* rescheduledProfile = nullptr;
    DisplayLimits limits;
};

DisplayScene buildDisplayScene(const DisplaySceneInput& input);

// The scene of a finished job. A CAD the view cannot tessellate or section falls back to the
// reconstructed surface, with a warning in the scene (the job itself already checked the CAD).
DisplayScene buildDisplayScene(const JobResult& result, const DisplayLimits& limits = {});

} // namespace bladeaxis::job

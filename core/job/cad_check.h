#pragma once
// The job's check of the tool against the real blade (issue 6): the blade CAD (STEP/IGES, or the
// demo blade's own B-spline surface), tessellated and sampled once, then the original and the
// re-scheduled cutting pass checked for gouges and shank/holder collisions. An output program
// that gouges or collides is refused unless forced, with the first offending source line.

#include "core/base/error.h"
#include "core/cad/cad_files.h"
#include "core/cad/clearance.h"
#include "core/cad/tool_geometry.h"
#include "core/job/section_check.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::job {

struct CadCheckSpec {
    std::filesystem::path file;  // STEP or IGES; empty: no check (the demo uses its own surface)
    cad::Placement placement;    // of the blade relative to the rotary axis
    cad::ToolGeometry tool;      // ballRadius is taken from the job's tool radius
    double sampleSpacing = 0.25; // mm between surface samples of the clearance check
    bool force = false;          // write a program even if it gouges or collides
};

struct CadCheckResult {
    cad::CadShape blade;
    std::string source; // the CAD file name, or "demo blade surface"
    std::size_t faces = 0;
    std::size_t triangles = 0;
    cad::ClearanceReport original;
    std::optional<cad::ClearanceReport> rescheduled;
    std::vector<SectionComparison> sections; // CAD vs toolpath concave exits, per base point
};

struct CuttingPassView {
    std::span<const toolpath::ClRecord> original;
    std::span<const toolpath::ClRecord> rescheduled; // empty when not re-scheduled
    std::string sourceFile;
    std::vector<std::pair<std::size_t, std::size_t>> layers; // inclusive record ranges
};

// Tessellates and samples the blade once, then checks both passes. Errors: Geometry for meshing
// failures, InvalidArgument for a bad tool.
Result<CadCheckResult> runCadCheck(const CadCheckSpec& spec, const cad::CadShape& blade,
                                   std::string source, double toolRadius,
                                   const CuttingPassView& pass);

// Issues of the re-scheduled pass deeper than the original tool already is at the same CL point
// (by more than the mesh deflection). The ball centres are kept, so a gouge of the input's
// centres is the CAM's, not ours: it is reported as a warning, not counted here.
std::vector<cad::ClearanceIssue> introducedIssues(const CadCheckResult& result);

// The refusal of an output whose tool gouges or collides where the original did not:
// CheckFailed naming the first such CL point and its source line.
Status refuseIfColliding(const CadCheckResult& result, const std::string& sourceFile, bool force);

} // namespace bladeaxis::job

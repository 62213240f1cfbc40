#pragma once
// The job's check of the tool against the real blade (issue 6): the blade CAD (STEP/IGES, or the
// demo blade's own B-spline surface), tessellated and sampled once, then the original and the
// re-scheduled cutting pass checked for gouges and shank/holder collisions. An output program
// that gouges or collides anywhere is refused unless forced, with the first offending source
// line and whether the input program already did the same there.
//
// Only the cutting pass (the longest run of feed moves, the records the re-scheduling changes)
// is checked, not the approach, retract and rapid moves around it: those are written
// byte-identical to the input, so the output cannot change their clearance, and they are long
// straight moves between few points, which a check at the CL points (not swept) would not prove
// clear anyway. Checking the input's own links is the CAM's verifier's job.

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
    std::filesystem::path file; // STEP or IGES; empty: no check (the demo uses its own surface)
    cad::AxisRotationPlacement placement; // of the blade relative to the rotary axis
    cad::ToolGeometry tool;      // ballRadius and taperHalfAngle are the job's (jobTool below)
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

// The tool the check uses: spec's stick-out and holder with the job's ball radius and the taper
// the channel was built for (spec §2.3). Checked before any scheduling, so that a tool the check
// cannot model stops the job at once. Errors: InvalidArgument naming the command-line option
// and the job-file key of the size out of range, and the range.
Result<cad::ToolGeometry> jobTool(const cad::ToolGeometry& tool, double ballRadius,
                                  double taperHalfAngle);

// Tessellates and samples the blade once, then checks both passes. Errors: Geometry for meshing
// failures and for CAD that does not fit the program (cad_fit.h), InvalidArgument for a bad
// tool.
Result<CadCheckResult> runCadCheck(const CadCheckSpec& spec, const cad::CadShape& blade,
                                   std::string source, double toolRadius,
                                   const CuttingPassView& pass);

// Issues of the re-scheduled pass that the input program does not have: no issue of the same
// kind at the same CL point, or one shallower by more than the mesh deflection. For the report;
// the refusal below counts every issue of the output.
std::vector<cad::ClearanceIssue> introducedIssues(const CadCheckResult& result);

// The input's issue of the same kind at the same CL point, if any. The ball centres are kept, so
// an input ball gouge is in the output too: the CAM's, not the schedule's.
const cad::ClearanceIssue* inputIssueLike(const CadCheckResult& result,
                                          const cad::ClearanceIssue& issue);

// The refusal of an output program that gouges or collides anywhere (ball gouge, shank or holder
// collision beyond the check's tolerance), unless forced: CheckFailed naming the first such CL
// point's source line, its kind and depth, and whether the input program already had it there.
Status refuseIfColliding(const CadCheckResult& result, const std::string& sourceFile, bool force);

} // namespace bladeaxis::job

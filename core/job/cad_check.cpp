#include "core/job/cad_check.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/cad/surface_samples.h"
#include "core/cad/tessellation.h"
#include "core/job/cad_fit.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace bladeaxis::job {

namespace {

Result<cad::ClearanceReport> check(const cad::SurfaceSamples& samples,
                                   std::span<const toolpath::ClRecord> records,
                                   const cad::ToolGeometry& tool, const CuttingPassView& pass) {
    toolpath::Toolpath path;
    path.sourceFile = pass.sourceFile;
    path.records.assign(records.begin(), records.end());
    cad::ClearanceOptions options;
    options.layers = pass.layers;
    return cad::checkClearance(samples, path, tool, options);
}

Status toolError(const std::string& message) {
    return makeError(ErrorCode::InvalidArgument, "tool for the clearance check: " + message);
}

bool positive(double value) {
    return std::isfinite(value) && value > 0.0;
}

} // namespace

Result<cad::ToolGeometry> jobTool(const cad::ToolGeometry& tool, double ballRadius,
                                  double taperHalfAngle) {
    cad::ToolGeometry result = tool;
    result.ballRadius = ballRadius;
    result.taperHalfAngle = taperHalfAngle;
    const std::string maxTaperDeg = formatTrimmed(units::radToDeg(cad::kMaxTaperHalfAngle), 3);
    if (!std::isfinite(taperHalfAngle) || taperHalfAngle < 0.0 ||
        taperHalfAngle >= cad::kMaxTaperHalfAngle) {
        return std::unexpected(
            toolError("--taper-deg (job file: parameters.taper_deg) must lie in [0, " +
                      maxTaperDeg + ") deg, got " +
                      formatTrimmed(units::radToDeg(taperHalfAngle), 3) +
                      " deg; the shank model of the check takes no wider taper")
                .error());
    }
    const std::pair<const char*, double> sizes[] = {
        {"--tool-radius (job file: tool_radius_mm)", ballRadius},
        {"--stick-out", tool.stickOut},
        {"--holder-radius", tool.holderRadius},
        {"--holder-length", tool.holderLength}};
    for (const auto& [name, value] : sizes) {
        if (!positive(value)) {
            return std::unexpected(toolError(std::string(name) +
                                             " must be a positive length in mm, got " +
                                             formatTrimmed(value, 3))
                                       .error());
        }
    }
    if (tool.stickOut <= 2.0 * ballRadius) {
        return std::unexpected(
            toolError("--stick-out (" + formatTrimmed(tool.stickOut, 3) +
                      " mm) must exceed the ball diameter, 2 x --tool-radius = " +
                      formatTrimmed(2.0 * ballRadius, 3) + " mm")
                .error());
    }
    // Whatever cad::validate checks beyond the names above still stops the job here.
    if (Status valid = cad::validate(result); !valid) {
        return std::unexpected(valid.error());
    }
    return result;
}

Result<CadCheckResult> runCadCheck(const CadCheckSpec& spec, const cad::CadShape& blade,
                                   std::string source, double toolRadius,
                                   const CuttingPassView& pass) {
    auto checkedTool = jobTool(spec.tool, toolRadius, spec.tool.taperHalfAngle);
    if (!checkedTool) {
        return std::unexpected(checkedTool.error());
    }
    const cad::ToolGeometry& tool = *checkedTool;
    auto mesh = cad::tessellate(blade);
    if (!mesh) {
        return std::unexpected(mesh.error());
    }
    auto samples = cad::SurfaceSamples::create(*mesh, spec.sampleSpacing);
    if (!samples) {
        return std::unexpected(samples.error());
    }
    CadCheckResult result;
    result.blade = blade;
    result.source = std::move(source);
    result.faces = static_cast<std::size_t>(blade.faceCount());
    result.triangles = mesh->triangles.size();
    auto original = check(*samples, pass.original, tool, pass);
    if (!original) {
        return std::unexpected(original.error());
    }
    result.original = std::move(*original);
    std::vector<Vec3> centres;
    centres.reserve(pass.original.size());
    for (const toolpath::ClRecord& record : pass.original) {
        centres.push_back(toolpath::ballCentre(record, toolRadius));
    }
    const std::string cadName = spec.file.empty() ? result.source : spec.file.string();
    if (Status fits = checkCadFitsProgram({.blade = &*mesh,
                                           .clearance = &result.original,
                                           .centres = centres,
                                           .toolRadius = toolRadius,
                                           .searchLimit = cad::ClearanceOptions{}.searchLimit,
                                           .cadName = cadName,
                                           .programName = pass.sourceFile});
        !fits) {
        return std::unexpected(fits.error());
    }
    if (!pass.rescheduled.empty()) {
        auto rescheduled = check(*samples, pass.rescheduled, tool, pass);
        if (!rescheduled) {
            return std::unexpected(rescheduled.error());
        }
        result.rescheduled = std::move(*rescheduled);
    }
    return result;
}

namespace {

constexpr double kResolution = 0.01; // mm, the tessellation's linear deflection

std::string inputVerdict(const CadCheckResult& result, const cad::ClearanceIssue& first) {
    const cad::ClearanceIssue* before = inputIssueLike(result, first);
    if (before == nullptr) {
        return "the input program does not: the new orientation causes it";
    }
    const std::string verb = first.kind == cad::ClearanceKind::Gouge ? "gouges" : "collides";
    return "the input program already " + verb + " there, " + formatFixed(before->depth, 3) +
           " mm deep" +
           (first.kind == cad::ClearanceKind::Gouge
                ? " (the ball centres are the input's and are kept: the CAM's gouge)"
                : "");
}

} // namespace

const cad::ClearanceIssue* inputIssueLike(const CadCheckResult& result,
                                          const cad::ClearanceIssue& issue) {
    const auto& issues = result.original.issues; // in record order
    auto it = std::ranges::lower_bound(issues, issue.record, {}, &cad::ClearanceIssue::record);
    for (; it != issues.end() && it->record == issue.record; ++it) {
        if (it->kind == issue.kind) {
            return &*it;
        }
    }
    return nullptr;
}

std::vector<cad::ClearanceIssue> introducedIssues(const CadCheckResult& result) {
    std::vector<cad::ClearanceIssue> introduced;
    if (!result.rescheduled) {
        return introduced;
    }
    for (const cad::ClearanceIssue& issue : result.rescheduled->issues) {
        const cad::ClearanceIssue* before = inputIssueLike(result, issue);
        if (before == nullptr || issue.depth > before->depth + kResolution) {
            introduced.push_back(issue);
        }
    }
    return introduced;
}

Status refuseIfColliding(const CadCheckResult& result, const std::string& sourceFile, bool force) {
    if (force || !result.rescheduled || result.rescheduled->issues.empty()) {
        return {};
    }
    const auto& issues = result.rescheduled->issues;
    const std::size_t inherited = issues.size() - introducedIssues(result).size();
    return makeError(ErrorCode::CheckFailed,
                     "the re-scheduled program gouges or collides with " + result.source + " at " +
                         std::to_string(issues.size()) + " CL points (" +
                         std::to_string(inherited) + " of them as the input program already " +
                         "does); first: " + cad::describe(issues.front(), sourceFile) + "; " +
                         inputVerdict(result, issues.front()) +
                         "; nothing was written (use --force to write it anyway)",
                     {sourceFile});
}

} // namespace bladeaxis::job

#include "core/job/cad_check.h"

#include "core/base/number_io.h"
#include "core/cad/surface_samples.h"
#include "core/cad/tessellation.h"

#include <algorithm>

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

} // namespace

Result<CadCheckResult> runCadCheck(const CadCheckSpec& spec, const cad::CadShape& blade,
                                   std::string source, double toolRadius,
                                   const CuttingPassView& pass) {
    cad::ToolGeometry tool = spec.tool;
    tool.ballRadius = toolRadius;
    if (auto valid = cad::validate(tool); !valid) {
        return std::unexpected(valid.error());
    }
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
    if (!pass.rescheduled.empty()) {
        auto rescheduled = check(*samples, pass.rescheduled, tool, pass);
        if (!rescheduled) {
            return std::unexpected(rescheduled.error());
        }
        result.rescheduled = std::move(*rescheduled);
    }
    return result;
}

std::vector<cad::ClearanceIssue> introducedIssues(const CadCheckResult& result) {
    std::vector<cad::ClearanceIssue> introduced;
    if (!result.rescheduled) {
        return introduced;
    }
    // Where the input's tool is already in the surface (the ball, when the CAM's centres dip
    // into a twisted blade), a new orientation at the channel limit may take the shank as deep
    // as the ball, not deeper: only what goes beyond the input's own depth at that CL point, by
    // more than the mesh deflection, is ours.
    constexpr double kResolution = 0.01; // mm, the tessellation's linear deflection
    const auto& before = result.original.records;
    for (const cad::ClearanceIssue& issue : result.rescheduled->issues) {
        const cad::RecordClearance& was = before[issue.record];
        const cad::RecordClearance& now = result.rescheduled->records[issue.record];
        const double allowed = std::min({0.0, was.ball, was.shank, was.holder}) - kResolution;
        const double clearance = issue.kind == cad::ClearanceKind::Gouge            ? now.ball
                                 : issue.kind == cad::ClearanceKind::ShankCollision ? now.shank
                                                                                    : now.holder;
        if (clearance < allowed) {
            introduced.push_back(issue);
        }
    }
    return introduced;
}

Status refuseIfColliding(const CadCheckResult& result, const std::string& sourceFile, bool force) {
    const std::vector<cad::ClearanceIssue> issues = introducedIssues(result);
    if (force || issues.empty()) {
        return {};
    }
    return makeError(ErrorCode::CheckFailed,
                     "the re-scheduled tool gouges or collides with the blade where the original "
                     "does not (" +
                         std::to_string(issues.size()) +
                         " CL points; first: " + cad::describe(issues.front(), sourceFile) +
                         "); nothing was written (use --force to write it anyway)",
                     {sourceFile});
}

} // namespace bladeaxis::job

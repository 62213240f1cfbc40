#include "core/cad/clearance.h"

#include "core/base/number_io.h"
#include "core/base/parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>

namespace bladeaxis::cad {
namespace {

struct ToolPose {
    Vec3 centre; // Q
    Vec3 axis;   // V, unit
};

Result<std::vector<ToolPose>> poses(const toolpath::Toolpath& path, double radius) {
    std::vector<ToolPose> result;
    result.reserve(path.records.size());
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const toolpath::ClRecord& record = path.records[i];
        const double length = record.axis.norm();
        if (!record.tip.allFinite() || !record.axis.allFinite() || !(length > 1e-12)) {
            return makeError(ErrorCode::Geometry,
                             "clearance: record " + std::to_string(i) +
                                 " has a non-finite tip or a zero tool axis",
                             {path.sourceFile, record.line, 0});
        }
        const Vec3 axis = record.axis / length;
        result.push_back({record.tip + radius * axis, axis});
    }
    return result;
}

RecordClearance clearanceAt(const SurfaceSamples& blade, const ToolPose& pose,
                            const ToolGeometry& tool, const AxialFrustum& shank,
                            const AxialFrustum& holder, double limit) {
    const Vec3 q = pose.centre, v = pose.axis;
    const double radius = tool.ballRadius;
    auto inFrame = [&](const AxialFrustum& solid) {
        return [&, solid](const Vec3& p) {
            const Vec3 d = p - q;
            const double t = d.dot(v);
            return signedDistance(solid, t, (d - t * v).norm());
        };
    };
    RecordClearance result;
    result.ball = blade.minimum([&](const Vec3& p) { return (p - q).norm() - radius; }, limit);
    result.shank = blade.minimum(inFrame(shank), limit);
    result.holder = blade.minimum(inFrame(holder), limit);
    return result;
}

// One layer per revolution of Q about x: the unwrapped polar angle in (y, z), counted from the
// first record in the direction the path turns overall.
std::vector<std::pair<std::size_t, std::size_t>> revolutions(const std::vector<ToolPose>& poses) {
    std::vector<double> angle(poses.size(), 0.0);
    for (std::size_t i = 0; i < poses.size(); ++i) {
        angle[i] = std::atan2(poses[i].centre.z(), poses[i].centre.y());
        if (i > 0) {
            angle[i] = angle[i - 1] + std::remainder(angle[i] - angle[i - 1], 2 * std::numbers::pi);
        }
    }
    const double sense = (!angle.empty() && angle.back() < angle.front()) ? -1.0 : 1.0;
    std::vector<std::pair<std::size_t, std::size_t>> layers;
    long current = 0;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const auto turn = static_cast<long>(
            std::floor(sense * (angle[i] - angle.front()) / (2 * std::numbers::pi)));
        if (layers.empty() || turn > current) {
            layers.push_back({i, i});
            current = turn;
        } else {
            layers.back().second = i;
        }
    }
    return layers;
}

Status checkInputs(const ToolGeometry& tool, const ClearanceOptions& options, std::size_t count) {
    if (Status ok = validate(tool); !ok) {
        return ok;
    }
    if (!(options.gougeTolerance >= 0.0) || !std::isfinite(options.gougeTolerance) ||
        !std::isfinite(options.minimumClearance) || !(options.searchLimit > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "clearance: the gouge tolerance must be >= 0 mm, the minimum clearance "
                         "finite and the search limit > 0 mm");
    }
    std::size_t expected = 0;
    for (const auto& [first, last] : options.layers) {
        if (first != expected || last < first || last >= count) {
            return makeError(ErrorCode::InvalidArgument,
                             "clearance: layer ranges must cover the records in order, without "
                             "gaps or overlaps");
        }
        expected = last + 1;
    }
    if (!options.layers.empty() && expected != count) {
        return makeError(ErrorCode::InvalidArgument,
                         "clearance: the layer ranges do not reach the last record");
    }
    return {};
}

void addIssues(const toolpath::Toolpath& path, const ClearanceOptions& options,
               ClearanceReport& report) {
    for (std::size_t i = 0; i < report.records.size(); ++i) {
        const RecordClearance& c = report.records[i];
        const int line = path.records[i].line;
        if (c.ball < -options.gougeTolerance) {
            report.issues.push_back({i, line, ClearanceKind::Gouge, -c.ball});
        }
        if (c.shank < options.minimumClearance) {
            report.issues.push_back(
                {i, line, ClearanceKind::ShankCollision, options.minimumClearance - c.shank});
        }
        if (c.holder < options.minimumClearance) {
            report.issues.push_back(
                {i, line, ClearanceKind::HolderCollision, options.minimumClearance - c.holder});
        }
    }
}

void summariseLayers(const std::vector<std::pair<std::size_t, std::size_t>>& ranges,
                     ClearanceReport& report) {
    std::size_t issue = 0;
    for (const auto& [first, last] : ranges) {
        LayerClearance layer{
            first, last, minimumOf(std::span(report.records).subspan(first, last - first + 1)), 0};
        for (; issue < report.issues.size() && report.issues[issue].record <= last; ++issue) {
            ++layer.issues;
        }
        report.layers.push_back(layer);
    }
}

} // namespace

RecordClearance minimumOf(std::span<const RecordClearance> records) {
    constexpr double kFar = std::numeric_limits<double>::infinity();
    RecordClearance minimum{kFar, kFar, kFar};
    for (const RecordClearance& record : records) {
        minimum.ball = std::min(minimum.ball, record.ball);
        minimum.shank = std::min(minimum.shank, record.shank);
        minimum.holder = std::min(minimum.holder, record.holder);
    }
    return minimum;
}

const char* toString(ClearanceKind kind) {
    switch (kind) {
    case ClearanceKind::Gouge:
        return "gouge";
    case ClearanceKind::ShankCollision:
        return "shank collision";
    case ClearanceKind::HolderCollision:
        return "holder collision";
    }
    return "clearance issue";
}

std::string describe(const ClearanceIssue& issue, const std::string& sourceFile) {
    const SourceLocation where{sourceFile, issue.line, 0};
    return where.toString() + ": " + toString(issue.kind) + " " + formatFixed(issue.depth, 3) +
           " mm deep (record " + std::to_string(issue.record) + ")";
}

Result<ClearanceReport> checkClearance(const SurfaceSamples& blade, const toolpath::Toolpath& path,
                                       const ToolGeometry& tool, const ClearanceOptions& options) {
    if (Status ok = checkInputs(tool, options, path.records.size()); !ok) {
        return std::unexpected(ok.error());
    }
    const Result<std::vector<ToolPose>> toolPoses = poses(path, tool.ballRadius);
    if (!toolPoses) {
        return std::unexpected(toolPoses.error());
    }
    ClearanceReport report;
    report.samplingError = blade.coverageRadius();
    report.records.resize(toolPoses->size());
    const AxialFrustum shank = shankSolid(tool);
    const AxialFrustum holder = holderSolid(tool);
    // Records are independent: workers take blocks of them from a shared counter.
    constexpr std::size_t kBlock = 64;
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t begin = next.fetch_add(kBlock); begin < toolPoses->size();
             begin = next.fetch_add(kBlock)) {
            const std::size_t end = std::min(begin + kBlock, toolPoses->size());
            for (std::size_t i = begin; i < end; ++i) {
                report.records[i] =
                    clearanceAt(blade, (*toolPoses)[i], tool, shank, holder, options.searchLimit);
            }
        }
    };
    const unsigned threads = currentThreadCount(); // the caller's context (execution.h)
    {
        std::vector<std::jthread> pool;
        for (unsigned t = 1; t < threads; ++t) {
            pool.emplace_back(worker);
        }
        worker();
    }
    addIssues(path, options, report);
    if (!report.records.empty()) {
        summariseLayers(options.layers.empty() ? revolutions(*toolPoses) : options.layers, report);
    }
    return report;
}

} // namespace bladeaxis::cad

#include "core/job/section_check.h"

#include "core/base/units.h"
#include "core/cad/sections.h"
#include "core/scheduling/curvature_states.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::job {

namespace {

constexpr double kStepMm = 0.25; // resampling of the section before the curvature analysis

// The section as a closed polygon in (y, z), resampled at about kStepMm.
std::vector<Vec2> resampled(const cad::Polyline3& line) {
    std::vector<Vec2> points;
    const std::size_t n = line.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = line.points[i];
        const Vec3& b = line.points[(i + 1) % n];
        const double length = std::hypot(b.y() - a.y(), b.z() - a.z());
        const int pieces = std::max(1, static_cast<int>(std::ceil(length / kStepMm)));
        for (int k = 0; k < pieces; ++k) {
            const double t = static_cast<double>(k) / pieces;
            points.emplace_back(a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z()));
        }
    }
    return points;
}

// Concave-run exits of a counter-clockwise closed section, as angles about the rotary axis of
// the ball centre there (the exit offset by R along the outward normal): the engine works on
// ball centres, so this compares like with like.
std::vector<double> concaveExitAngles(const cad::Polyline3& line, double toolRadius) {
    const std::vector<Vec2> p = resampled(line);
    const std::size_t n = p.size();
    if (n < 8) {
        return {};
    }
    std::vector<double> s(n, 0.0), turning(n, 0.0), curvature(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 before = p[i] - p[(i + n - 1) % n];
        const Vec2 after = p[(i + 1) % n] - p[i];
        turning[i] = std::atan2(before.x() * after.y() - before.y() * after.x(), before.dot(after));
        const double ds = 0.5 * (before.norm() + after.norm());
        curvature[i] = ds > 0.0 ? turning[i] / ds : 0.0;
        s[i] = i == 0 ? 0.0 : s[i - 1] + before.norm();
    }
    scheduling::CurvatureSettings settings;
    settings.mergeGapMm = 2.0 * toolRadius; // the engine's defaults (Appendix A)
    settings.minRunMm = 2.0 * toolRadius;
    const auto analysis = scheduling::analyseCurvature(s, curvature, turning, settings);
    std::vector<double> exits;
    for (const scheduling::ConcaveRun& run : analysis.runs) {
        const std::size_t i = run.exit % n;
        const Vec2 tangent = (p[(i + 1) % n] - p[(i + n - 1) % n]).normalized();
        const Vec2 outward(tangent.y(), -tangent.x()); // right of a counter-clockwise contour
        const Vec2 centre = p[i] + toolRadius * outward;
        exits.push_back(std::atan2(centre.y(), centre.x()));
    }
    return exits;
}

const cad::Polyline3* longestClosed(const std::vector<cad::Polyline3>& lines) {
    const cad::Polyline3* best = nullptr;
    for (const cad::Polyline3& line : lines) {
        if (line.closed && (best == nullptr || line.points.size() > best->points.size())) {
            best = &line;
        }
    }
    return best;
}

bool isFallback(const scheduling::ScheduleResult& schedule, std::size_t basePoint) {
    for (const scheduling::LayerResult& layer : schedule.layers) {
        if (layer.first == basePoint || layer.last == basePoint) {
            if (std::find(layer.flags.begin(), layer.flags.end(),
                          scheduling::LayerStatus::NoConcaveRun) != layer.flags.end()) {
                return true;
            }
        }
    }
    return false;
}

} // namespace

Result<std::vector<SectionComparison>>
compareConcaveExits(const cad::CadShape& blade, const scheduling::ScheduleResult& schedule,
                    std::span<const Vec3> centres, double toolRadius) {
    std::vector<double> xs;
    for (std::size_t base : schedule.basePoints) {
        xs.push_back(centres[base].x());
    }
    auto sections = cad::sectionsAtX(blade, xs);
    if (!sections) {
        return std::unexpected(sections.error());
    }
    std::vector<SectionComparison> comparisons;
    for (std::size_t k = 0; k < schedule.basePoints.size(); ++k) {
        const std::size_t base = schedule.basePoints[k];
        SectionComparison c;
        c.basePoint = base;
        c.x = xs[k];
        const double engine = std::atan2(centres[base].z(), centres[base].y());
        c.engineExitDeg = units::radToDeg(engine);
        c.engineFallback = isFallback(schedule, base);
        if (const cad::Polyline3* section = longestClosed((*sections)[k])) {
            const std::vector<double> exits = concaveExitAngles(*section, toolRadius);
            c.cadConcaveRuns = exits.size();
            double nearest = 1e9;
            for (double exit : exits) {
                const double difference = std::abs(std::remainder(exit - engine, 2.0 * M_PI));
                if (difference < nearest) {
                    nearest = difference;
                    c.cadExitDeg = units::radToDeg(exit);
                    c.differenceDeg = units::radToDeg(difference);
                }
            }
        }
        comparisons.push_back(c);
    }
    return comparisons;
}

} // namespace bladeaxis::job

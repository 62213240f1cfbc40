#include "core/blade/closed_curve.h"

#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace bladeaxis::blade {
namespace {

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Relative difference below which the two sides of a section count as equally far from the
// chord (symmetric sections, up to round-off of the generator).
constexpr double kSymmetricSideTolerance = 1e-6;

} // namespace

double signedArea(std::span<const Vec2> curve) {
    double twiceArea = 0.0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
        twiceArea += cross(curve[i], curve[(i + 1) % curve.size()]);
    }
    return 0.5 * twiceArea;
}

Vec2 areaCentroid(std::span<const Vec2> curve) {
    // Relative to vertex 0 to keep the products small for curves far from the origin.
    const Vec2 origin = curve.empty() ? Vec2::Zero() : curve[0];
    double twiceArea = 0.0;
    Vec2 moment = Vec2::Zero();
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const Vec2 a = curve[i] - origin;
        const Vec2 b = curve[(i + 1) % curve.size()] - origin;
        const double c = cross(a, b);
        twiceArea += c;
        moment += c * (a + b);
    }
    if (twiceArea == 0.0) {
        return origin;
    }
    return origin + moment / (3.0 * twiceArea);
}

double perimeter(std::span<const Vec2> curve) {
    double length = 0.0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
        length += (curve[(i + 1) % curve.size()] - curve[i]).norm();
    }
    return length;
}

Result<Curve2> normaliseClosedCurve(std::span<const Vec2> curve, std::string_view what) {
    Curve2 points;
    points.reserve(curve.size());
    for (std::size_t i = 0; i < curve.size(); ++i) {
        if (!curve[i].allFinite()) {
            return makeError(ErrorCode::Geometry,
                             std::string(what) + ": point " + std::to_string(i) + " is not finite");
        }
        if (points.empty() || (curve[i] - points.back()).norm() > 1e-9) {
            points.push_back(curve[i]);
        }
    }
    while (points.size() > 1 && (points.back() - points.front()).norm() <= 1e-9) {
        points.pop_back();
    }
    if (points.size() < 3) {
        return makeError(ErrorCode::Geometry, std::string(what) + ": needs at least 3 distinct " +
                                                  "points, got " + std::to_string(points.size()));
    }
    const double area = signedArea(points);
    const double scale = perimeter(points);
    if (!(std::abs(area) > 1e-12 * scale * scale)) {
        return makeError(ErrorCode::Geometry, std::string(what) + ": the curve encloses no area (" +
                                                  formatShortest(area) + " mm^2)");
    }
    if (area < 0.0) {
        std::reverse(points.begin() + 1, points.end());
    }
    return points;
}

Curve2 resampleByArcLength(std::span<const Vec2> curve, int count) {
    Curve2 result;
    if (curve.empty() || count <= 0) {
        return result;
    }
    const double total = perimeter(curve);
    result.reserve(static_cast<std::size_t>(count));
    std::size_t edge = 0;
    double edgeStart = 0.0;
    for (int k = 0; k < count; ++k) {
        const double target = total * static_cast<double>(k) / count;
        double edgeLength = (curve[(edge + 1) % curve.size()] - curve[edge]).norm();
        while (edgeStart + edgeLength < target && edge + 1 < curve.size()) {
            edgeStart += edgeLength;
            ++edge;
            edgeLength = (curve[(edge + 1) % curve.size()] - curve[edge]).norm();
        }
        const double t =
            edgeLength > 0.0 ? std::clamp((target - edgeStart) / edgeLength, 0.0, 1.0) : 0.0;
        result.push_back(curve[edge] + t * (curve[(edge + 1) % curve.size()] - curve[edge]));
    }
    return result;
}

Curve2 rotateToStart(std::span<const Vec2> curve, std::size_t start) {
    Curve2 result(curve.begin(), curve.end());
    if (!result.empty()) {
        std::rotate(result.begin(), result.begin() + static_cast<long>(start % result.size()),
                    result.end());
    }
    return result;
}

double distanceToCurve(const Vec2& p, std::span<const Vec2> curve) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const Vec2& a = curve[i];
        const Vec2 edge = curve[(i + 1) % curve.size()] - a;
        const double lengthSq = edge.squaredNorm();
        const double t = lengthSq > 0.0 ? std::clamp((p - a).dot(edge) / lengthSq, 0.0, 1.0) : 0.0;
        best = std::min(best, (a + t * edge - p).norm());
    }
    return best;
}

std::size_t phaseIndex(std::span<const Vec2> curve, const Vec2& preferredSide, Vec2* side) {
    std::size_t a = 0;
    std::size_t b = 0;
    double farthest = -1.0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
        for (std::size_t j = i + 1; j < curve.size(); ++j) {
            const double d = (curve[j] - curve[i]).squaredNorm();
            if (d > farthest) {
                farthest = d;
                a = i;
                b = j;
            }
        }
    }
    const Vec2 chord = (curve[b] - curve[a]).normalized();
    const Vec2 normal(-chord.y(), chord.x());
    std::size_t bestPlus = 0;
    std::size_t bestMinus = 0;
    double plus = -1.0;
    double minus = -1.0;
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const double d = (curve[i] - curve[a]).dot(normal);
        if (d > plus) {
            plus = d;
            bestPlus = i;
        }
        if (-d > minus) {
            minus = -d;
            bestMinus = i;
        }
    }
    bool takePlus = plus > minus;
    if (std::abs(plus - minus) <= kSymmetricSideTolerance * std::max(plus, minus)) {
        takePlus = normal.dot(preferredSide) >= 0.0;
    }
    if (side != nullptr) {
        *side = takePlus ? normal : Vec2(-normal);
    }
    return takePlus ? bestPlus : bestMinus;
}

} // namespace bladeaxis::blade

#include "core/blade/offset_curve.h"

#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace bladeaxis::blade {
namespace {

// Per-vertex and per-edge quantities of a closed polygon. turn[k] is the signed turning at
// vertex k (positive = convex for a counter-clockwise curve), edge k runs from vertex k to k+1.
struct PolygonFrame {
    std::vector<Vec2> direction;
    std::vector<double> edgeLength;
    std::vector<double> normalAngle; // angle of the outward normal of edge k
    std::vector<double> turn;
};

PolygonFrame frameOf(std::span<const Vec2> curve) {
    const std::size_t n = curve.size();
    PolygonFrame frame;
    frame.direction.resize(n);
    frame.edgeLength.resize(n);
    frame.normalAngle.resize(n);
    frame.turn.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 edge = curve[(k + 1) % n] - curve[k];
        frame.edgeLength[k] = edge.norm();
        frame.direction[k] = edge / frame.edgeLength[k];
        frame.normalAngle[k] = std::atan2(-frame.direction[k].x(), frame.direction[k].y());
    }
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2& in = frame.direction[(k + n - 1) % n];
        const Vec2& out = frame.direction[k];
        frame.turn[k] = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
    }
    return frame;
}

// Length by which a segment is shortened at a vertex: R tan(|turn|/2) at concave vertices.
double trimFactor(double turn) {
    return turn < 0.0 ? std::tan(-0.5 * turn) : 0.0;
}

} // namespace

double minConcaveRadius(std::span<const Vec2> curve) {
    if (curve.size() < 3) {
        return std::numeric_limits<double>::infinity();
    }
    const PolygonFrame frame = frameOf(curve);
    const std::size_t n = curve.size();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
        const double trim = trimFactor(frame.turn[k]) + trimFactor(frame.turn[(k + 1) % n]);
        if (trim > 0.0) {
            best = std::min(best, frame.edgeLength[k] / trim);
        }
    }
    return best;
}

Result<OffsetCurve> OffsetCurve::create(std::span<const Vec2> section, double radius) {
    if (!(radius > 0.0) || !std::isfinite(radius)) {
        return makeError(ErrorCode::InvalidArgument,
                         "tool radius R = " + formatShortest(radius) + " mm must be > 0");
    }
    if (section.size() < 3) {
        return makeError(ErrorCode::Geometry, "offset curve: the section has fewer than 3 points");
    }
    for (std::size_t k = 0; k < section.size(); ++k) {
        const double edge = (section[(k + 1) % section.size()] - section[k]).norm();
        if (!(edge > 1e-12)) { // also catches NaN points
            return makeError(ErrorCode::Geometry, "offset curve: section edge " +
                                                      std::to_string(k) +
                                                      " has zero length or is not finite");
        }
    }
    const double concave = minConcaveRadius(section);
    if (!(radius < concave)) {
        return makeError(ErrorCode::Geometry,
                         "tool radius R = " + formatShortest(radius) +
                             " mm is not smaller than the minimum concave radius of curvature " +
                             formatTrimmed(concave, 4) +
                             " mm of the section: the offset curve would intersect itself");
    }
    const PolygonFrame frame = frameOf(section);
    const std::size_t n = section.size();
    OffsetCurve curve;
    curve.m_radius = radius;
    curve.m_vertexCount = n;
    curve.m_pieces.reserve(2 * n);
    double s = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double turn = frame.turn[k];
        if (turn > 0.0) { // convex vertex: arc about the vertex
            const double start = frame.normalAngle[(k + n - 1) % n];
            curve.m_pieces.push_back(Piece{section[k], section[k], start, turn, s, radius * turn, k,
                                           0.0, 0.0, 0.0, 0.0});
            s += radius * turn;
        }
        const double trimStart = radius * trimFactor(turn);
        const double trimEnd = radius * trimFactor(frame.turn[(k + 1) % n]);
        const double length = std::max(frame.edgeLength[k] - trimStart - trimEnd, 0.0);
        const Vec2 from = section[k] + trimStart * frame.direction[k];
        const Vec2 to = from + length * frame.direction[k];
        const double edge = frame.edgeLength[k];
        // At a concave end the normal turns by `turn` (< 0); the blend meets the bisector there.
        const double blendStart = frame.normalAngle[k] - 0.5 * std::min(turn, 0.0);
        const double blendEnd = frame.normalAngle[k] + 0.5 * std::min(frame.turn[(k + 1) % n], 0.0);
        curve.m_pieces.push_back(Piece{from, to, frame.normalAngle[k], 0.0, s, length, k,
                                       trimStart / edge, (trimStart + length) / edge, blendStart,
                                       blendEnd});
        s += length;
    }
    curve.m_length = s;
    return curve;
}

OffsetSample OffsetCurve::at(double fraction) const {
    double wrapped = fraction - std::floor(fraction);
    const double s = std::clamp(wrapped, 0.0, 1.0) * m_length;
    auto it =
        std::upper_bound(m_pieces.begin(), m_pieces.end(), s,
                         [](double value, const Piece& piece) { return value < piece.start; });
    const Piece& piece = *(it == m_pieces.begin() ? it : std::prev(it));
    const double t =
        piece.length > 0.0 ? std::clamp((s - piece.start) / piece.length, 0.0, 1.0) : 0.0;
    OffsetSample sample;
    const double angle = piece.angleStart + t * piece.angleSweep;
    sample.normal = Vec2(std::cos(angle), std::sin(angle));
    sample.contact = piece.contactStart + t * (piece.contactEnd - piece.contactStart);
    sample.centre = sample.contact + m_radius * sample.normal;
    const double blend = piece.angleSweep != 0.0
                             ? angle
                             : piece.blendStart + t * (piece.blendEnd - piece.blendStart);
    sample.blendedNormal = Vec2(std::cos(blend), std::sin(blend));
    sample.edge = piece.edge;
    sample.edgeFraction = piece.fractionStart + t * (piece.fractionEnd - piece.fractionStart);
    return sample;
}

} // namespace bladeaxis::blade

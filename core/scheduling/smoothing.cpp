#include "core/scheduling/smoothing.h"

#include "core/scheduling/detail/corner_channel.h"
#include "core/scheduling/detail/exact_epsilon.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace bladeaxis::scheduling {

namespace {

using detail::ChannelView;

struct CornerFrame {
    Vec2 p2;
    double k1, k2;   // slopes in rad/mm
    double dS1, dS2; // horizontal segment lengths, mm
    double f1, f2;   // share of each segment this corner may use (§5.4)
};

BezierPair pairFor(const CornerFrame& c, double epsilon, CornerForm form) {
    if (form == CornerForm::GraphLimit) {
        return graphLimitCornerPair(c.p2, c.k1, c.k2, epsilon);
    }
    return euclideanCornerPair(c.p2, std::atan(c.k1), std::atan(c.k2), epsilon);
}

double geometricLimit(const CornerFrame& c, CornerForm form) {
    if (form == CornerForm::GraphLimit) {
        return graphLimitEpsilonLimit(c.k1, c.k2, c.dS1, c.dS2, c.f1, c.f2);
    }
    return euclideanEpsilonLimit(std::atan(c.k1), std::atan(c.k2), std::hypot(c.dS1, c.k1 * c.dS1),
                                 std::hypot(c.dS2, c.k2 * c.dS2), c.f1, c.f2);
}

// Paper epsilon0 (W1): the least vertical room between polyline and the boundary on the
// corner's side, over the span from mid-point to mid-point (whole segment at layer ends).
double paperRoom(const CornerFrame& c, const ChannelView& channel) {
    double room = std::numeric_limits<double>::infinity();
    const std::size_t end = channel.upperIndex(c.p2.x() + c.f2 * c.dS2);
    for (std::size_t j = channel.lowerIndex(c.p2.x() - c.f1 * c.dS1); j < end; ++j) {
        const double x = channel.s[j];
        const double poly = c.p2.y() + (x < c.p2.x() ? c.k1 : c.k2) * (x - c.p2.x());
        room = std::min(room, c.k2 > c.k1 ? channel.rawMax[j] - poly : poly - channel.rawMin[j]);
    }
    return room;
}

// [X] The plateau corner: W <= f1 dS1 and f2 dS2 (the span of the graph-limit pair), then the
// paper's room (epsilon0 rule) or the exact rule on W.
SmoothedCorner smoothPlateau(const CornerFrame& c, const ChannelView& channel,
                             const SmoothingSettings& settings) {
    SmoothedCorner corner;
    corner.s = c.p2.x();
    corner.profile = CornerProfile::Plateau;
    const double geometric = std::min(c.f1 * c.dS1, c.f2 * c.dS2);
    double halfWidth = geometric;
    if (settings.rule == EpsilonRule::Paper) {
        const double room = paperRoom(c, channel) - settings.finalClearanceRad;
        halfWidth = std::min(geometric, plateauHalfWidth(c.k1, c.k2, std::max(room, 0.0)));
    } else {
        halfWidth = detail::exactPlateauHalfWidth(c.p2, c.k1, c.k2, geometric, channel,
                                                  settings.checksPerCubic, settings.bisectionSteps);
    }
    if (!(halfWidth > 0.0)) {
        return corner; // unsmoothed corner, flagged by limitedBy = None
    }
    corner.plateau = {c.p2, c.k1, c.k2, halfWidth};
    corner.epsilon = corner.plateau.epsilon();
    corner.limitedBy = halfWidth >= geometric ? CornerLimit::Geometry : CornerLimit::Channel;
    return corner;
}

SmoothedCorner smoothOne(const CornerFrame& c, const ChannelView& channel,
                         const SmoothingSettings& settings) {
    if (settings.form == CornerForm::GraphLimit && settings.profile == CornerProfile::Plateau) {
        return smoothPlateau(c, channel, settings);
    }
    SmoothedCorner corner;
    corner.s = c.p2.x();
    const double sign = c.k2 > c.k1 ? 1.0 : -1.0;
    const double geometric = geometricLimit(c, settings.form);
    double magnitude = geometric;
    if (settings.rule == EpsilonRule::Paper) {
        magnitude = std::min(geometric, paperRoom(c, channel) - settings.finalClearanceRad);
    } else {
        const detail::CornerGeometry shape =
            detail::cornerGeometry(c.p2, c.k1, c.k2, sign, pairFor(c, sign, settings.form));
        magnitude = detail::exactEpsilon(shape, geometric, channel, settings.checksPerCubic,
                                         settings.bisectionSteps);
    }
    if (!(magnitude > 0.0)) {
        return corner; // unsmoothed corner, flagged by limitedBy = None
    }
    corner.epsilon = sign * magnitude;
    corner.limitedBy = magnitude >= geometric ? CornerLimit::Geometry : CornerLimit::Channel;
    corner.curve = pairFor(c, corner.epsilon, settings.form);
    return corner;
}

} // namespace

SmoothedPath smoothCorners(std::span<const PolyVertex> vertices, std::span<const double> s,
                           std::span<const double> rawMin, std::span<const double> rawMax,
                           const SmoothingSettings& settings) {
    SmoothedPath path;
    path.vertices.assign(vertices.begin(), vertices.end());
    path.form = settings.form;
    const ChannelView channel{s, rawMin, rawMax, settings.finalClearanceRad};
    path.corners.reserve(vertices.size());
    for (std::size_t k = 1; k + 1 < vertices.size(); ++k) {
        const PolyVertex& a = vertices[k - 1];
        const PolyVertex& b = vertices[k];
        const PolyVertex& c = vertices[k + 1];
        CornerFrame frame{{b.s, b.theta},
                          (b.theta - a.theta) / (b.s - a.s),
                          (c.theta - b.theta) / (c.s - b.s),
                          b.s - a.s,
                          c.s - b.s,
                          // [A] f = 1 towards a layer end (no corner there), else 1/2.
                          k == 1 ? 1.0 : 0.5,
                          k + 2 == vertices.size() ? 1.0 : 0.5};
        if (std::abs(std::atan(frame.k2) - std::atan(frame.k1)) < 1e-12) {
            continue; // no corner (§5.4)
        }
        SmoothedCorner corner = smoothOne(frame, channel, settings);
        corner.vertex = k;
        path.corners.push_back(corner);
    }
    return path;
}

PathSamples evaluateSmoothedPath(const SmoothedPath& path, std::span<const double> s) {
    PathSamples out;
    out.theta.resize(s.size());
    out.dTheta.resize(s.size());
    out.ddTheta.resize(s.size());
    const std::vector<PolyVertex>& v = path.vertices;
    std::size_t segment = 0;
    std::size_t corner = 0;
    const CubicBezier* cubic = nullptr;
    std::optional<CubicGraph> graph; // of *cubic
    double parameter = -1.0;         // warm start along the current cubic (none yet)
    for (std::size_t i = 0; i < s.size(); ++i) {
        while (corner < path.corners.size() &&
               (path.corners[corner].limitedBy == CornerLimit::None ||
                path.corners[corner].sEnd() < s[i])) {
            ++corner;
        }
        if (corner < path.corners.size() && path.corners[corner].sBegin() <= s[i] &&
            path.corners[corner].profile == CornerProfile::Plateau) {
            const GraphPoint p = path.corners[corner].plateau.at(s[i]); // explicit in S
            out.theta[i] = p.value;
            out.dTheta[i] = p.first;
            out.ddTheta[i] = p.second;
            continue;
        }
        if (corner < path.corners.size() && path.corners[corner].sBegin() <= s[i]) {
            const BezierPair& pair = path.corners[corner].curve;
            // The cubic evaluatePair would choose.
            const CubicBezier* current =
                s[i] <= pair.first.control[3].x() ? &pair.first : &pair.second;
            if (current != cubic) {
                cubic = current;
                graph.emplace(*cubic);
                parameter = -1.0;
            }
            const GraphPoint p = graph->at(s[i], parameter);
            out.theta[i] = p.value;
            out.dTheta[i] = p.first;
            out.ddTheta[i] = p.second;
            continue;
        }
        while (segment + 2 < v.size() && v[segment + 1].s < s[i]) {
            ++segment;
        }
        if (v.size() < 2) {
            out.theta[i] = v.empty() ? 0.0 : v.front().theta;
            continue;
        }
        const PolyVertex& a = v[segment];
        const PolyVertex& b = v[segment + 1];
        out.dTheta[i] = (b.theta - a.theta) / (b.s - a.s);
        out.theta[i] = a.theta + out.dTheta[i] * (s[i] - a.s);
        out.ddTheta[i] = 0.0;
    }
    return out;
}

double peakSecondDerivative(const SmoothedPath& path) {
    // Graph limit: theta''(t) = (2 eps / (3 h^2)) t (1 - t) / (1 - 2t + 2t^2)^3 on both cubics
    // (§5.6), symmetric about t = 1/2 and maximal there; the dense sampling below includes
    // t = 1/2, so one evaluation gives the same peak.
    const int samples = path.form == CornerForm::GraphLimit ? 0 : 64;
    double peak = 0.0;
    for (const SmoothedCorner& corner : path.corners) {
        if (corner.limitedBy == CornerLimit::None) {
            continue;
        }
        if (corner.profile == CornerProfile::Plateau) {
            peak = std::max(peak, corner.plateau.peak()); // theta'' = A (1 - v^4): |A| at S2
            continue;
        }
        for (const CubicBezier* cubic : {&corner.curve.first, &corner.curve.second}) {
            if (samples == 0) {
                peak = std::max(peak, std::abs(secondDerivativeAt(*cubic, 0.5)));
            }
            for (int k = 0; k <= samples && samples > 0; ++k) {
                const double t = static_cast<double>(k) / samples;
                peak = std::max(peak, std::abs(secondDerivativeAt(*cubic, t)));
            }
        }
    }
    return peak;
}

} // namespace bladeaxis::scheduling

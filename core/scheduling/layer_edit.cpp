#include "core/scheduling/layer_edit.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/scheduling/layer_scheduler.h"
#include "core/scheduling/linearisation.h"
#include "core/scheduling/smoothing.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace bladeaxis::scheduling {
namespace {

std::size_t nearestSample(std::span<const double> s, double value) {
    const auto upper = std::lower_bound(s.begin(), s.end(), value);
    if (upper == s.begin()) {
        return 0;
    }
    if (upper == s.end()) {
        return s.size() - 1;
    }
    const auto lower = std::prev(upper);
    const auto chosen = (value - *lower <= *upper - value) ? lower : upper;
    return static_cast<std::size_t>(std::distance(s.begin(), chosen));
}

// Key points are named 1-based, as the editor's table counts them, and amounts in degrees with
// two decimals, as the editor shows them.
std::string pointName(std::size_t index) {
    return "key point " + std::to_string(index + 1);
}

std::string degrees(double radians) {
    return formatFixed(units::radToDeg(radians), 2) + " deg";
}

Result<std::vector<PolyVertex>> snapToSamples(const LayerResult& layer,
                                              std::span<const Vec2> vertices) {
    if (vertices.size() < 2) {
        return makeError(ErrorCode::InvalidArgument, "a layer needs at least two key points");
    }
    std::vector<PolyVertex> snapped;
    for (const Vec2& vertex : vertices) {
        if (!std::isfinite(vertex.x()) || !std::isfinite(vertex.y())) {
            return makeError(ErrorCode::InvalidArgument, "a key point is not a finite number");
        }
        const std::size_t index = nearestSample(layer.s, vertex.x());
        if (!snapped.empty() && index <= snapped.back().index) {
            return makeError(
                ErrorCode::InvalidArgument,
                pointName(snapped.size()) + " is not after " + pointName(snapped.size() - 1) +
                    " in S: key points are at increasing S, one sample apart at least");
        }
        snapped.push_back({index, layer.s[index], vertex.y(), false});
    }
    snapped.front().fixed = true;
    snapped.back().fixed = true;
    return snapped;
}

// The ends join the neighbouring layers: an edit may not move them.
Status checkEnds(const LayerResult& layer, std::span<const PolyVertex> vertices, double tol) {
    const Vec2& first = layer.polyline.front();
    const Vec2& last = layer.polyline.back();
    const bool sameStart =
        vertices.front().index == 0 && std::abs(vertices.front().theta - first.y()) <= tol;
    const bool sameEnd = vertices.back().index == layer.s.size() - 1 &&
                         std::abs(vertices.back().theta - last.y()) <= tol;
    if (!sameStart) {
        return makeError(ErrorCode::InvalidArgument,
                         pointName(0) + " joins the layer before and stays: it moved by " +
                             degrees(std::abs(vertices.front().theta - first.y())));
    }
    if (!sameEnd) {
        return makeError(ErrorCode::InvalidArgument,
                         pointName(vertices.size() - 1) +
                             " joins the layer after and stays: it moved by " +
                             degrees(std::abs(vertices.back().theta - last.y())));
    }
    return {};
}

Status checkMonotone(std::span<const PolyVertex> vertices, double tol) {
    const double direction = vertices.back().theta >= vertices.front().theta ? 1.0 : -1.0;
    for (std::size_t i = 1; i < vertices.size(); ++i) {
        const double step = (vertices[i].theta - vertices[i - 1].theta) * direction;
        if (step < -tol) {
            return makeError(ErrorCode::InvalidArgument,
                             pointName(i) + " turns theta(S) back by " + degrees(-step) + " from " +
                                 pointName(i - 1) + ": the rotary axis would reverse");
        }
    }
    return {};
}

Status checkInsideHull(const LayerResult& layer, std::span<const PolyVertex> vertices, double tol) {
    for (std::size_t v = 1; v < vertices.size(); ++v) {
        const PolyVertex& a = vertices[v - 1];
        const PolyVertex& b = vertices[v];
        for (std::size_t i = a.index; i <= b.index; ++i) {
            const double t = (layer.s[i] - a.s) / (b.s - a.s);
            const double theta = a.theta + t * (b.theta - a.theta);
            if (theta < layer.lo[i] - tol || theta > layer.hi[i] + tol) {
                const double outside =
                    theta < layer.lo[i] ? layer.lo[i] - theta : theta - layer.hi[i];
                return makeError(ErrorCode::InvalidArgument,
                                 "the segment from " + pointName(v - 1) + " to " + pointName(v) +
                                     " leaves the channel by " + degrees(outside) +
                                     " at S = " + formatFixed(layer.s[i], 2) + " mm");
            }
        }
    }
    return {};
}

} // namespace

Result<LayerResult> resmoothLayer(const LayerResult& layer, std::span<const Vec2> vertices,
                                  const ScheduleParameters& parameters) {
    if (layer.s.size() < 2 || layer.polyline.size() < 2) {
        return makeError(ErrorCode::InvalidArgument, "the layer has no schedule to edit");
    }
    Result<std::vector<PolyVertex>> snapped = snapToSamples(layer, vertices);
    if (!snapped) {
        return std::unexpected(snapped.error());
    }
    const double tol = parameters.keyToleranceRad;
    for (const Status& check : {checkEnds(layer, *snapped, tol), checkMonotone(*snapped, tol),
                                checkInsideHull(layer, *snapped, tol)}) {
        if (!check) {
            return std::unexpected(check.error());
        }
    }
    const SmoothingSettings settings{
        parameters.epsilonRule,         parameters.cornerForm,
        parameters.finalClearanceRad,   parameters.epsilonBisectionSteps,
        parameters.curveChecksPerCubic, parameters.cornerProfile};
    const SmoothedPath smooth =
        smoothCorners(*snapped, layer.s, layer.thetaMin, layer.thetaMax, settings);

    LayerResult edited = layer;
    edited.keyPoints.clear();
    edited.polyline.clear();
    for (const PolyVertex& vertex : *snapped) {
        edited.keyPoints.emplace_back(vertex.s, vertex.theta);
        edited.polyline.emplace_back(vertex.s, vertex.theta);
    }
    edited.corners.clear();
    for (const SmoothedCorner& corner : smooth.corners) {
        edited.corners.push_back({corner.s, corner.epsilon, cornerBound(corner.limitedBy)});
    }
    PathSamples samples = evaluateSmoothedPath(smooth, layer.s);
    edited.theta = std::move(samples.theta);
    edited.dTheta = std::move(samples.dTheta);
    edited.ddTheta = std::move(samples.ddTheta);
    const double peak = peakSecondDerivative(smooth);
    edited.peakSecondDerivative = std::isfinite(peak) ? peak : 0.0;
    edited.minClearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < edited.theta.size(); ++i) {
        edited.minClearance = std::min({edited.minClearance, edited.theta[i] - edited.thetaMin[i],
                                        edited.thetaMax[i] - edited.theta[i]});
    }
    return edited;
}

} // namespace bladeaxis::scheduling

#pragma once
// Spec §5.4 and §5.8: one Bezier pair per polyline corner, epsilon by the paper's epsilon0
// rule or by exact bisection against the raw channel, and the analytic evaluation of the
// smoothed theta(S), theta'(S), theta''(S) at the layer samples.

#include "core/scheduling/bezier_corner.h"
#include "core/scheduling/linearisation.h"
#include "core/scheduling/schedule_parameters.h"

#include <span>
#include <vector>

namespace bladeaxis::scheduling {

enum class CornerLimit { Geometry, Channel, None }; // None: left unsmoothed (G0 there)

struct SmoothedCorner {
    std::size_t vertex = 0; // index into the polyline
    double s = 0.0;         // S2, mm
    double epsilon = 0.0;   // signed vertical offset of the joint, rad
    CornerLimit limitedBy = CornerLimit::None;
    CornerProfile profile = CornerProfile::Bezier;
    BezierPair curve;      // the Bezier pair (profile Bezier)
    PlateauCorner plateau; // the plateau corner (profile Plateau)

    double sBegin() const {
        return profile == CornerProfile::Plateau ? plateau.sBegin() : curve.sBegin();
    }
    double sEnd() const {
        return profile == CornerProfile::Plateau ? plateau.sEnd() : curve.sEnd();
    }
};

struct SmoothingSettings {
    EpsilonRule rule = EpsilonRule::Exact;
    CornerForm form = CornerForm::GraphLimit;
    double finalClearanceRad = 0.0;
    int bisectionSteps = 40;
    int checksPerCubic = 64;
    // [X] Graph-limit corners only (the Euclidean form is always the Bezier pair). The default
    // is ScheduleParameters' default, for callers that build the settings without it.
    CornerProfile profile = CornerProfile::Plateau;
};

struct SmoothedPath {
    std::vector<PolyVertex> vertices;    // the polyline that was smoothed
    std::vector<SmoothedCorner> corners; // increasing S, spans pairwise disjoint
    CornerForm form = CornerForm::Euclidean;
};

// `rawMin`, `rawMax`: the raw channel of the layer relative to its reference (no margin).
SmoothedPath smoothCorners(std::span<const PolyVertex> vertices, std::span<const double> s,
                           std::span<const double> rawMin, std::span<const double> rawMax,
                           const SmoothingSettings& settings);

struct PathSamples {
    std::vector<double> theta, dTheta, ddTheta; // rad, rad/mm, rad/mm^2
};

// theta, theta', theta'' at abscissae `s` (increasing); straight segments outside the corner
// spans, the Bezier pair inside (spec §5.8).
PathSamples evaluateSmoothedPath(const SmoothedPath& path, std::span<const double> s);

// Peak |theta''| of the smoothed curve: at t = 1/2 of every graph-limit cubic, where §5.6 puts
// the maximum; from a dense parameter sampling of every Euclidean cubic.
double peakSecondDerivative(const SmoothedPath& path);

} // namespace bladeaxis::scheduling

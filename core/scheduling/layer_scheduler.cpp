#include "core/scheduling/layer_scheduler.h"

#include "core/scheduling/linearisation.h"
#include "core/scheduling/smoothing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace bladeaxis::scheduling {

namespace {

struct Attempt {
    double rho = 0.0;
    LeadChoice leads;
    Linearisation lines;
    SmoothedPath smooth;
    double peak = std::numeric_limits<double>::infinity();
};

Attempt attempt(const LayerProblem& p, const ScheduleParameters& parameters, double rho) {
    Attempt a;
    a.rho = rho;
    const double tol = parameters.keyToleranceRad;
    if (!p.shortLayer) {
        a.leads = chooseLeads(p.s, p.lo, p.hi, p.startValue, p.endValue, rho, p.span.startFree,
                              p.span.endFree, tol);
    }
    a.lines =
        linearise({p.s, p.lo, p.hi, p.startValue, p.endValue, a.leads, parameters.keyMode, tol});
    const SmoothingSettings settings{parameters.epsilonRule, parameters.cornerForm,
                                     parameters.finalClearanceRad, parameters.epsilonBisectionSteps,
                                     parameters.curveChecksPerCubic};
    a.smooth = smoothCorners(a.lines.vertices, p.s, p.rawMin, p.rawMax, settings);
    a.peak = peakSecondDerivative(a.smooth);
    return a;
}

// §3.4 lead_mode = auto: golden-section search of rho minimising the peak |theta''|; the best
// attempt seen is kept, because the objective is piecewise (leads snap to samples).
Attempt bestAttempt(const LayerProblem& p, const ScheduleParameters& parameters) {
    if (parameters.leadMode == LeadMode::Fixed || p.shortLayer ||
        (p.span.startFree && p.span.endFree)) {
        return attempt(p, parameters, parameters.leadFraction);
    }
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    double low = parameters.leadSearchMinFraction;
    double high = parameters.leadSearchMaxFraction;
    Attempt best = attempt(p, parameters, parameters.leadFraction);
    auto consider = [&](double rho) {
        Attempt a = attempt(p, parameters, rho);
        const double peak = a.peak;
        if (peak < best.peak) {
            best = std::move(a);
        }
        return peak;
    };
    double x1 = high - ratio * (high - low);
    double x2 = low + ratio * (high - low);
    double f1 = consider(x1);
    double f2 = consider(x2);
    for (int k = 2; k < parameters.leadSearchEvaluations; ++k) {
        if (f1 <= f2) {
            high = x2;
            x2 = x1;
            f2 = f1;
            x1 = high - ratio * (high - low);
            f1 = consider(x1);
        } else {
            low = x1;
            x1 = x2;
            f1 = f2;
            x2 = low + ratio * (high - low);
            f2 = consider(x2);
        }
    }
    return best;
}

LayerResult::Corner::Bound boundOf(CornerLimit limit) {
    switch (limit) {
    case CornerLimit::Geometry:
        return LayerResult::Corner::Bound::Geometry;
    case CornerLimit::Channel:
        return LayerResult::Corner::Bound::Channel;
    case CornerLimit::None:
        break;
    }
    return LayerResult::Corner::Bound::None;
}

void fillCommon(LayerResult& r, const LayerProblem& p) {
    r.s = p.s;
    r.thetaOriginal = p.original;
    r.thetaMin = p.rawMin;
    r.thetaMax = p.rawMax;
    r.lo = p.lo;
    r.hi = p.hi;
    r.flags = p.flags;
    r.junctionAngle = p.reference;
}

void fillSchedule(LayerResult& r, const Attempt& a, const LayerProblem& p) {
    for (const PolyVertex& v : a.lines.keyPoints) {
        r.keyPoints.emplace_back(v.s, v.theta);
    }
    for (const PolyVertex& v : a.lines.vertices) {
        r.polyline.emplace_back(v.s, v.theta);
    }
    for (const SmoothedCorner& c : a.smooth.corners) {
        r.corners.push_back({c.s, c.epsilon, boundOf(c.limitedBy)});
    }
    PathSamples samples = evaluateSmoothedPath(a.smooth, p.s);
    r.theta = std::move(samples.theta);
    r.dTheta = std::move(samples.dTheta);
    r.ddTheta = std::move(samples.ddTheta);
    r.leadFraction = a.rho;
    r.peakSecondDerivative = std::isfinite(a.peak) ? a.peak : 0.0;
}

double minClearance(const LayerResult& r) {
    double clearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < r.theta.size(); ++i) {
        clearance = std::min({clearance, r.theta[i] - r.thetaMin[i], r.thetaMax[i] - r.theta[i]});
    }
    return clearance;
}

} // namespace

void finiteDifferences(std::span<const double> s, std::span<const double> values,
                       std::vector<double>& first, std::vector<double>& second) {
    const std::size_t n = s.size();
    first.assign(n, 0.0);
    second.assign(n, 0.0);
    for (std::size_t i = 0; i < n && n >= 3; ++i) {
        const std::size_t c = std::clamp<std::size_t>(i, 1, n - 2); // one-sided at the ends
        const double hm = s[c] - s[c - 1];
        const double hp = s[c + 1] - s[c];
        const double dm = values[c] - values[c - 1];
        const double dp = values[c + 1] - values[c];
        second[i] = 2.0 * (hm * dp - hp * dm) / (hm * hp * (hm + hp));
        const double centre = (hm * hm * dp + hp * hp * dm) / (hm * hp * (hm + hp));
        first[i] = centre + second[i] * (s[i] - s[c]);
    }
}

LayerOutcome scheduleLayer(const LayerProblem& problem, const ScheduleParameters& parameters,
                           std::vector<std::size_t> inputIndex, std::size_t layerNumber) {
    const auto started = std::chrono::steady_clock::now();
    LayerOutcome out;
    LayerResult& r = out.result;
    fillCommon(r, problem);
    r.inputIndex = std::move(inputIndex);
    r.first = r.inputIndex.empty() ? 0 : r.inputIndex.front();
    r.last = r.inputIndex.empty() ? 0 : r.inputIndex.back();
    const bool keepOriginal = std::find(problem.flags.begin(), problem.flags.end(),
                                        LayerStatus::MonotoneInfeasible) != problem.flags.end();
    if (keepOriginal) {
        r.theta = problem.original;
        finiteDifferences(problem.s, r.theta, r.dTheta, r.ddTheta);
    } else {
        const Attempt best = bestAttempt(problem, parameters);
        fillSchedule(r, best, problem);
        if (best.leads.zeroLengthLead) {
            out.warnings.push_back("layer " + std::to_string(layerNumber) +
                                   ": the base point is pinched, one-sample lead used");
        }
        for (const SmoothedCorner& c : best.smooth.corners) {
            if (c.limitedBy == CornerLimit::None) {
                out.warnings.push_back("layer " + std::to_string(layerNumber) + ": corner at S = " +
                                       std::to_string(c.s) + " mm left unsmoothed");
            }
        }
    }
    if (r.flags.empty()) {
        r.flags.push_back(LayerStatus::Ok);
    }
    r.minClearance = minClearance(r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return out;
}

} // namespace bladeaxis::scheduling

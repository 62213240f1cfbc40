#include "core/scheduling/layer_scheduler.h"

#include "core/scheduling/linearisation.h"
#include "core/scheduling/smoothing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace bladeaxis::scheduling {

namespace {

struct Attempt {
    double rho = 0.0;
    LeadChoice leads;
    Linearisation lines;
    SmoothedPath smooth;
    double peak = std::numeric_limits<double>::infinity();
};

Attempt attempt(const LayerProblem& p, const ScheduleParameters& parameters, double rho,
                const LeadChoice& leads) {
    Attempt a;
    a.rho = rho;
    a.leads = leads;
    const double tol = parameters.keyToleranceRad;
    a.lines = linearise({p.s, p.lo, p.hi, p.startValue, p.endValue, a.leads, parameters.keyMode,
                         tol, parameters.adjust, 0.1 * parameters.marginRad});
    const SmoothingSettings settings{
        parameters.epsilonRule,         parameters.cornerForm,
        parameters.finalClearanceRad,   parameters.epsilonBisectionSteps,
        parameters.curveChecksPerCubic, parameters.cornerProfile};
    a.smooth = smoothCorners(a.lines.vertices, p.s, p.rawMin, p.rawMax, settings);
    a.peak = peakSecondDerivative(a.smooth);
    return a;
}

// The lead search (§3.4). An attempt depends on rho only through the lead samples, and the
// golden section soon narrows below one sample spacing: attempts are memoised by their leads,
// which returns exactly what re-running them would (a repeat never replaces the best, whose
// peak it only equals).
class LeadSearch {
  public:
    LeadSearch(const LayerProblem& problem, const ScheduleParameters& parameters)
        : m_problem(problem), m_parameters(parameters),
          m_limits(problem.shortLayer
                       ? LeadLimits{}
                       : leadLimits(problem.s, problem.lo, problem.hi, problem.startValue,
                                    problem.endValue, parameters.keyToleranceRad)) {}

    // Peak |theta''| at rho; keeps the best attempt (the first one reaching the lowest peak).
    double consider(double rho) {
        const LeadChoice leads = leadsAt(rho);
        for (const Seen& seen : m_seen) {
            if (seen.leadIn == leads.leadIn && seen.leadOut == leads.leadOut) {
                return seen.peak;
            }
        }
        Attempt a = attempt(m_problem, m_parameters, rho, leads);
        m_seen.push_back({leads.leadIn, leads.leadOut, a.peak});
        if (!m_best || a.peak < m_best->peak) {
            m_best = std::move(a);
        }
        return m_seen.back().peak;
    }

    Attempt takeBest() { return std::move(*m_best); }

  private:
    struct Seen {
        std::optional<std::size_t> leadIn, leadOut;
        double peak;
    };

    LeadChoice leadsAt(double rho) const {
        if (m_problem.shortLayer) {
            return {};
        }
        return chooseLeads(m_problem.s, m_limits, rho, m_problem.span.startFree,
                           m_problem.span.endFree);
    }

    const LayerProblem& m_problem;
    const ScheduleParameters& m_parameters;
    LeadLimits m_limits;
    std::vector<Seen> m_seen;
    std::optional<Attempt> m_best;
};

// §3.4 lead_mode = auto: golden-section search of rho minimising the peak |theta''|; the best
// attempt seen is kept, because the objective is piecewise (leads snap to samples).
Attempt bestAttempt(const LayerProblem& p, const ScheduleParameters& parameters) {
    LeadSearch search(p, parameters);
    search.consider(parameters.leadFraction);
    if (parameters.leadMode == LeadMode::Fixed || p.shortLayer ||
        (p.span.startFree && p.span.endFree)) {
        return search.takeBest();
    }
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    double low = parameters.leadSearchMinFraction;
    double high = parameters.leadSearchMaxFraction;
    double x1 = high - ratio * (high - low);
    double x2 = low + ratio * (high - low);
    double f1 = search.consider(x1);
    double f2 = search.consider(x2);
    for (int k = 2; k < parameters.leadSearchEvaluations; ++k) {
        if (f1 <= f2) {
            high = x2;
            x2 = x1;
            f2 = f1;
            x1 = high - ratio * (high - low);
            f1 = search.consider(x1);
        } else {
            low = x1;
            x1 = x2;
            f1 = f2;
            x2 = low + ratio * (high - low);
            f2 = search.consider(x2);
        }
    }
    return search.takeBest();
}

// The problem's per-sample vectors become the result's diagnostics (moved, not copied).
void fillCommon(LayerResult& r, LayerProblem&& p) {
    r.s = std::move(p.s);
    r.thetaOriginal = std::move(p.original);
    r.thetaMin = std::move(p.rawMin);
    r.thetaMax = std::move(p.rawMax);
    r.lo = std::move(p.lo);
    r.hi = std::move(p.hi);
    r.flags = std::move(p.flags);
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
        r.corners.push_back({c.s, c.epsilon, cornerBound(c.limitedBy)});
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

// §2.5 allow_nonmonotone: the original clamped into the raw channel, then a few passes of a
// [1 2 1] / 4 filter, each clamped into the channel again, the ends at the layer's start and end
// values (the junctions, clamped into the channel). [A] The
// spec says only "project and smooth"; the filter removes sample-to-sample noise of the input
// while never leaving the channel.
std::vector<double> projectedOriginal(const LayerProblem& p) {
    constexpr int kPasses = 4;
    std::vector<double> theta(p.original.size());
    for (std::size_t i = 0; i < theta.size(); ++i) {
        theta[i] = std::clamp(p.original[i], p.rawMin[i], std::max(p.rawMin[i], p.rawMax[i]));
    }
    if (theta.size() >= 2) { // the junction values where they are inside: continuity
        theta.front() = std::clamp(p.startValue, p.rawMin.front(),
                                   std::max(p.rawMin.front(), p.rawMax.front()));
        theta.back() =
            std::clamp(p.endValue, p.rawMin.back(), std::max(p.rawMin.back(), p.rawMax.back()));
    }
    std::vector<double> next = theta;
    for (int pass = 0; pass < kPasses; ++pass) {
        for (std::size_t i = 1; i + 1 < theta.size(); ++i) {
            const double average = 0.25 * (theta[i - 1] + 2.0 * theta[i] + theta[i + 1]);
            next[i] = std::clamp(average, p.rawMin[i], std::max(p.rawMin[i], p.rawMax[i]));
        }
        std::swap(theta, next);
    }
    return theta;
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

LayerOutcome scheduleLayer(LayerProblem problem, const ScheduleParameters& parameters,
                           std::vector<std::size_t> inputIndex, std::size_t layerNumber) {
    const auto started = std::chrono::steady_clock::now();
    LayerOutcome out;
    LayerResult& r = out.result;
    const bool keepOriginal = std::find(problem.flags.begin(), problem.flags.end(),
                                        LayerStatus::MonotoneInfeasible) != problem.flags.end();
    if (keepOriginal && parameters.allowNonmonotone) {
        r.theta = projectedOriginal(problem);
        finiteDifferences(problem.s, r.theta, r.dTheta, r.ddTheta);
        std::replace(problem.flags.begin(), problem.flags.end(), LayerStatus::MonotoneInfeasible,
                     LayerStatus::NonMonotone);
        out.warnings.push_back("layer " + std::to_string(layerNumber) +
                               ": no monotone path, the projected original is used "
                               "(the rotary axis may reverse)");
    } else if (keepOriginal) {
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
    fillCommon(r, std::move(problem));
    r.inputIndex = std::move(inputIndex);
    r.first = r.inputIndex.empty() ? 0 : r.inputIndex.front();
    r.last = r.inputIndex.empty() ? 0 : r.inputIndex.back();
    if (r.flags.empty()) {
        r.flags.push_back(LayerStatus::Ok);
    }
    r.minClearance = minClearance(r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return out;
}

LayerResult::Corner::Bound cornerBound(CornerLimit limit) {
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

} // namespace bladeaxis::scheduling

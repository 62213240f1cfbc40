#include "core/analysis/time_optimal.h"

#include "core/analysis/constant_feed.h"
#include "core/analysis/detail/path_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace bladeaxis::analysis {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::size_t kAxes = kinematics::kAllAxes.size();

bool limited(double limit) {
    return std::isfinite(limit) && limit > 0.0;
}

// u >= slope * x + offset (lower) or u <= slope * x + offset (upper).
struct Line {
    double slope = 0.0, offset = 0.0;
    double at(double x) const { return slope * x + offset; }
};

// The path derivatives of every axis at one grid point and the state bound from velocities.
struct Stage {
    std::array<double, kAxes> first{}, second{}; // q', q''
    double maxState = kInfinity;                 // x bound from velocity, feed and q' = 0 axes
};

struct Bounds {
    std::array<Line, kAxes + 1> lower, upper;
    std::size_t lowers = 0, uppers = 0;
};

class Problem {
  public:
    // Stages are computed when needed, not stored: a million-sample path would otherwise hold
    // ~90 MB of derivatives that the profile already has.
    // The constraints hold at the points of `grid` (a grid point per sample misses a spike one
    // block wide).
    Problem(const AxisProfile& profile, const kinematics::MachineModel& machine,
            const detail::PathGrid& grid)
        : m_profile(profile), m_s(profile.pathParameter), m_grid(grid) {
        for (std::size_t j = 0; j < kAxes; ++j) {
            const auto& limits = machine.limit(kinematics::kAllAxes[j]);
            m_velocity[j] = limits.velocity;
            m_acceleration[j] = limits.acceleration;
            m_jerk[j] = limits.jerk;
        }
    }

    // The jerk heuristic's local reduction of the state bound. The scales are made on its first
    // reduction: without the heuristic every scale is 1 and needs no array.
    void scaleState(std::size_t i, double factor) {
        if (m_stateScale.empty()) {
            m_stateScale.assign(size(), 1.0);
        }
        m_stateScale[i] *= factor;
    }
    double stateScale(std::size_t i) const { return m_stateScale.empty() ? 1.0 : m_stateScale[i]; }
    double jerkLimit(std::size_t j) const { return m_jerk[j]; }

    Stage stage(std::size_t i) const {
        Stage stage;
        const double feed = m_profile.feed;
        const std::size_t sample = m_grid.interval(i);
        const double fraction = m_grid.fraction(i);
        for (std::size_t j = 0; j < kAxes; ++j) {
            const AxisSeries& series = m_profile.axes[j];
            const auto [first, second] = derivativesWithin(series, sample, fraction);
            stage.first[j] = first / feed;
            stage.second[j] = second / (feed * feed);
            const double q1 = std::abs(stage.first[j]);
            if (limited(m_velocity[j]) && q1 > 0.0) {
                stage.maxState = std::min(stage.maxState, std::pow(m_velocity[j] / q1, 2));
            }
            if (limited(m_acceleration[j]) && !significant(stage.first[j]) &&
                stage.second[j] != 0.0) {
                // q' = 0: only the centripetal term q'' x remains.
                stage.maxState =
                    std::min(stage.maxState, m_acceleration[j] / std::abs(stage.second[j]));
            }
        }
        stage.maxState = std::min(stage.maxState, feed * feed) * stateScale(i);
        return stage;
    }

    std::size_t size() const { return m_grid.size(); }
    double step(std::size_t i) const { return m_grid.step(i); }
    // The path parameter of grid point i, mm.
    double pathAt(std::size_t i) const { return m_grid.pathAt(i); }

    // The lines bounding u at stage i for a state x, with x_{i+1} in [0, next].
    Bounds bounds(std::size_t i, const Stage& stage, double next) const {
        Bounds b;
        for (std::size_t j = 0; j < kAxes; ++j) {
            if (!limited(m_acceleration[j]) || !significant(stage.first[j])) {
                continue;
            }
            // -a <= q' u + q'' x <= a  ->  u in [(-a - q'' x) / q', (a - q'' x) / q'] (q' > 0).
            const double q1 = stage.first[j], q2 = stage.second[j], a = m_acceleration[j];
            const Line low{-q2 / q1, (q1 > 0.0 ? -a : a) / q1};
            const Line high{-q2 / q1, (q1 > 0.0 ? a : -a) / q1};
            b.lower[b.lowers++] = low;
            b.upper[b.uppers++] = high;
        }
        const double twoStep = 2.0 * step(i);
        b.lower[b.lowers++] = {-1.0 / twoStep, 0.0};            // x_{i+1} >= 0
        b.upper[b.uppers++] = {-1.0 / twoStep, next / twoStep}; // x_{i+1} <= next
        return b;
    }

    // The largest x in [0, maxState] for which some u satisfies every bound: every lower line
    // must stay below every upper line, a condition linear in x for each pair.
    double largestControllable(std::size_t i, double next) const {
        const Stage s = stage(i);
        const Bounds b = bounds(i, s, next);
        double high = s.maxState;
        for (std::size_t l = 0; l < b.lowers; ++l) {
            for (std::size_t u = 0; u < b.uppers; ++u) {
                const double slope = b.lower[l].slope - b.upper[u].slope;
                const double room = b.upper[u].offset - b.lower[l].offset; // at x = 0, >= 0
                if (slope > 0.0) {
                    high = std::min(high, room / slope);
                }
            }
        }
        return std::max(high, 0.0);
    }

    // The largest path acceleration u for crossing interval i from rest to rest: accelerate
    // over its first half, brake over the second, reaching x = u Delta mid-way. The stage's
    // bounds hold for +-u at every state up to that: |q'| u + |q''| u Delta <= a per axis, and
    // u Delta within the velocity, feed and jerk-heuristic bound.
    double restToRestAcceleration(std::size_t i) const {
        const Stage s = stage(i);
        const double delta = step(i);
        double u = s.maxState / delta;
        for (std::size_t j = 0; j < kAxes; ++j) {
            const double demand = std::abs(s.first[j]) + std::abs(s.second[j]) * delta;
            if (limited(m_acceleration[j]) && demand > 0.0) {
                u = std::min(u, m_acceleration[j] / demand);
            }
        }
        return u;
    }

    // The largest feasible u at (i, x) with x_{i+1} <= next.
    double largestControl(std::size_t i, double x, double next) const {
        const Bounds b = bounds(i, stage(i), next);
        double u = kInfinity;
        for (std::size_t k = 0; k < b.uppers; ++k) {
            u = std::min(u, b.upper[k].at(x));
        }
        return u;
    }

  private:
    static bool significant(double derivative) { return std::abs(derivative) > 1e-12; }

    // An axis's velocity and acceleration (time derivatives at the feed) a fraction of the way
    // through interval `sample`. The acceleration is interpolated linearly and the velocity is
    // its integral, corrected linearly so that both ends match the samples: exact for the
    // default cubic spline (q'' linear, q' quadratic per interval), and a smooth blend of the
    // samples for the other derivative methods.
    std::pair<double, double> derivativesWithin(const AxisSeries& series, std::size_t sample,
                                                double fraction) const {
        if (fraction == 0.0 || series.still()) {
            return {series.velocityAt(sample), series.accelerationAt(sample)};
        }
        const double h = (m_s[sample + 1] - m_s[sample]) / m_profile.feed; // s at the feed
        const double v0 = series.velocity[sample], v1 = series.velocity[sample + 1];
        const double a0 = series.acceleration[sample], a1 = series.acceleration[sample + 1];
        const double integral = h * (a0 * fraction + (a1 - a0) * fraction * fraction / 2.0);
        const double mismatch = v1 - v0 - h * (a0 + a1) / 2.0;
        return {v0 + integral + fraction * mismatch, a0 + (a1 - a0) * fraction};
    }

    const AxisProfile& m_profile;
    const std::vector<double>& m_s;
    const detail::PathGrid& m_grid;
    std::vector<double> m_stateScale;
    std::array<double, kAxes> m_velocity{}, m_acceleration{}, m_jerk{};
};

Status validate(const AxisProfile& profile) {
    if (profile.pathParameter.size() < 2) {
        return makeError(ErrorCode::InvalidArgument,
                         "the time-optimal model needs at least 2 path samples");
    }
    if (!(profile.feed > 0.0) || !std::isfinite(profile.feed)) {
        return makeError(ErrorCode::InvalidArgument,
                         "the time-optimal model needs a positive programmed feed");
    }
    for (const AxisSeries& series : profile.axes) {
        const std::size_t samples = series.still() ? 0 : profile.pathParameter.size();
        if (series.velocity.size() != samples || series.acceleration.size() != samples) {
            return makeError(ErrorCode::InvalidArgument, "axis profile sizes differ");
        }
        // A NaN would silently pass every comparison of the passes and poison T2.
        for (std::size_t i = 0; i < series.velocity.size(); ++i) {
            if (!std::isfinite(series.velocity[i]) || !std::isfinite(series.acceleration[i])) {
                return makeError(ErrorCode::InvalidArgument,
                                 "the time-optimal model needs finite axis derivatives");
            }
        }
    }
    for (const double s : profile.pathParameter) {
        if (!std::isfinite(s)) {
            return makeError(ErrorCode::InvalidArgument,
                             "the time-optimal model needs a finite path parameter");
        }
    }
    return {};
}

// Backward and forward passes: T2 and the path speed per sample for the problem's bounds.
// The forward pass reads sample i + 1's controllable bound for the last time where it writes
// that sample's speed, so the speeds are written over the bounds: one array of 8 bytes per
// sample rather than two. Both passes look at the token every kIterationsPerCancelPoll samples
// (about a millisecond of either).
Result<TimeOptimalTime> parameterise(const Problem& problem, const CancelToken* cancel) {
    const std::size_t n = problem.size();
    std::vector<double> controllable(n, 0.0); // K_i = [0, controllable[i]]; rest at the end
    for (std::size_t i = n - 1; i-- > 0;) {
        if (isCancelledAt(cancel, i)) {
            return std::unexpected(cancelledError());
        }
        controllable[i] = problem.largestControllable(i, controllable[i + 1]);
    }
    TimeOptimalTime result;
    result.pathSpeed = std::move(controllable);
    const std::vector<double>& bound = result.pathSpeed; // sample i + 1's until step i
    result.pathSpeed[0] = 0.0;
    double x = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (isCancelledAt(cancel, i)) {
            return std::unexpected(cancelledError());
        }
        const double u = problem.largestControl(i, x, bound[i + 1]);
        const double next = std::clamp(x + 2.0 * problem.step(i) * u, 0.0, bound[i + 1]);
        const double speeds = std::sqrt(x) + std::sqrt(next);
        // A constant u cannot cross an interval that starts and ends at rest. The greedy pass
        // reaches rest before the last interval where a jagged path forces full braking at
        // the last but one sample (the A axis of a reciprocating original): cross it from rest
        // to rest instead, 2 sqrt(Delta / u).
        const double restAcceleration = speeds > 0.0 ? 0.0 : problem.restToRestAcceleration(i);
        if (!(speeds > 0.0) && !(restAcceleration > 0.0)) {
            return makeError(ErrorCode::Geometry,
                             "the axis limits do not let the tool move along the path near s = " +
                                 std::to_string(problem.pathAt(i)) + " mm");
        }
        result.time += speeds > 0.0 ? 2.0 * problem.step(i) / speeds
                                    : 2.0 * std::sqrt(problem.step(i) / restAcceleration);
        result.pathSpeed[i + 1] = std::sqrt(next);
        x = next;
    }
    result.peakPathSpeed = *std::max_element(result.pathSpeed.begin(), result.pathSpeed.end());
    return result;
}

// Sample i's axis accelerations along the parameterisation (sample n - 1 has none: the check
// never reads it).
std::array<double, kAxes> accelerationsAt(const Problem& problem, const TimeOptimalTime& result,
                                          std::size_t i) {
    const double v0 = result.pathSpeed[i], v1 = result.pathSpeed[i + 1];
    const double u = (v1 * v1 - v0 * v0) / (2.0 * problem.step(i));
    const Stage stage = problem.stage(i);
    std::array<double, kAxes> acceleration{};
    for (std::size_t j = 0; j < kAxes; ++j) {
        acceleration[j] = stage.first[j] * u + stage.second[j] * v0 * v0;
    }
    return acceleration;
}

// Marks the samples where an axis's numerical jerk exceeds its limit (and lowers their state
// bound by x0.9); returns whether any did. The accelerations and times of two neighbouring
// samples are all the check reads, so they are rolled along the path: arrays of them were 48
// bytes per sample beside T2's own, on a path of millions of samples. The scales lowered do
// not change an acceleration (a stage's derivatives do not depend on them).
bool lowerWhereJerky(Problem& problem, const TimeOptimalTime& result) {
    const std::size_t n = problem.size();
    if (n < 3) {
        return false;
    }
    bool lowered = false;
    double time = 0.0;
    std::array<double, kAxes> acceleration = accelerationsAt(problem, result, 0);
    for (std::size_t i = 0; i + 2 < n; ++i) {
        const double v0 = result.pathSpeed[i], v1 = result.pathSpeed[i + 1];
        const double nextTime = time + (v0 + v1 > 0.0 ? 2.0 * problem.step(i) / (v0 + v1) : 0.0);
        const std::array<double, kAxes> nextAcceleration = accelerationsAt(problem, result, i + 1);
        const double dt = nextTime - time;
        for (std::size_t j = 0; j < kAxes && dt > 0.0; ++j) {
            const double jerk = (nextAcceleration[j] - acceleration[j]) / dt;
            if (limited(problem.jerkLimit(j)) && std::abs(jerk) > problem.jerkLimit(j)) {
                problem.scaleState(i, 0.9);
                problem.scaleState(i + 1, 0.9);
                lowered = true;
                break;
            }
        }
        time = nextTime;
        acceleration = nextAcceleration;
    }
    return lowered;
}

// Each interval's share of T2 on a solved grid, for the refinement's choice of blocks. An
// interval crossed from rest to rest (both speeds 0) counts as 0: it has no share to compare.
std::vector<double> intervalTimes(const TimeOptimalTime& solved, const std::vector<double>& s,
                                  std::span<const std::uint32_t> steps) {
    const detail::PathGrid grid(s, steps);
    std::vector<double> times(steps.size(), 0.0);
    for (std::size_t g = 0; g + 1 < grid.size(); ++g) {
        const double speeds = solved.pathSpeed[g] + solved.pathSpeed[g + 1];
        if (speeds > 0.0) {
            times[grid.interval(g)] += 2.0 * grid.step(g) / speeds;
        }
    }
    return times;
}

Status validateSteps(const AxisProfile& profile, std::span<const std::uint32_t> steps) {
    if (!steps.empty() && (steps.size() + 1 != profile.pathParameter.size() ||
                           std::ranges::any_of(steps, [](std::uint32_t k) { return k == 0; }))) {
        return makeError(ErrorCode::InvalidArgument,
                         "the time-optimal grid needs one step count >= 1 per interval");
    }
    return {};
}

} // namespace

Result<TimeOptimalTime> timeOptimalTime(const AxisProfile& profile,
                                        const kinematics::MachineModel& machine,
                                        const TimeOptimalOptions& options) {
    if (auto status = validate(profile); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = validateSteps(profile, options.stepsPerInterval); !status) {
        return std::unexpected(status.error());
    }
    const detail::PathGrid grid =
        options.stepsPerInterval.empty()
            ? detail::PathGrid(profile.pathParameter,
                               std::max<std::size_t>(options.subdivisions, 1))
            : detail::PathGrid(profile.pathParameter, options.stepsPerInterval);
    Problem problem(profile, machine, grid);
    auto result = parameterise(problem, options.cancel);
    if (!result) {
        return result;
    }
    if (options.jerkHeuristic) {
        result->jerkWithinLimits = false;
        while (result->jerkRounds < options.maxJerkRounds) {
            if (!lowerWhereJerky(problem, *result)) {
                result->jerkWithinLimits = true;
                break;
            }
            const int rounds = result->jerkRounds + 1;
            result = parameterise(problem, options.cancel);
            if (!result) {
                return result;
            }
            result->jerkRounds = rounds;
            result->jerkWithinLimits = false;
        }
        if (result->jerkRounds == options.maxJerkRounds) {
            result->jerkWithinLimits = !lowerWhereJerky(problem, *result);
        }
    }
    result->constantFeedTime = constantFeedTime(profile, machine, false).time;
    return result;
}

Result<ConvergedTime> convergedTimeOptimal(const AxisProfile& profile,
                                           const kinematics::MachineModel& machine,
                                           const ConvergedTimeOptions& options) {
    auto first = timeOptimalTime(profile, machine, {.cancel = options.cancel});
    if (!first) {
        return std::unexpected(first.error());
    }
    const std::size_t intervals = profile.pathParameter.size() - 1;
    std::vector<std::uint32_t> steps(intervals, 1);
    std::vector<double> before = intervalTimes(*first, profile.pathParameter, steps);
    std::vector<std::uint8_t> refining(intervals, 1);
    ConvergedTime result{.time = first->time};
    while (result.subdivisions * 2 <= options.maxSubdivisions) {
        for (std::size_t i = 0; i < intervals; ++i) {
            steps[i] *= refining[i] ? 2 : 1;
        }
        auto finer = timeOptimalTime(profile, machine,
                                     {.cancel = options.cancel, .stepsPerInterval = steps});
        if (!finer) {
            return std::unexpected(finer.error());
        }
        result.lastChange = std::abs(finer->time - result.time) / std::max(finer->time, 1e-300);
        result.time = finer->time;
        result.subdivisions = *std::max_element(steps.begin(), steps.end());
        result.converged = result.lastChange < options.tolerance;
        if (result.converged) {
            break;
        }
        // A block whose time moved by less than half its even share of the tolerance stops
        // being refined: all such blocks together can move T2 by at most half the tolerance.
        const std::vector<double> after = intervalTimes(*finer, profile.pathParameter, steps);
        const double share = 0.5 * options.tolerance * result.time / static_cast<double>(intervals);
        bool any = false;
        for (std::size_t i = 0; i < intervals; ++i) {
            refining[i] = refining[i] && std::abs(after[i] - before[i]) > share;
            any = any || refining[i];
        }
        if (!any) {
            break;
        }
        before = after;
    }
    return result;
}

std::optional<ConvergedTime> convergedTimeOptimalOrNone(const AxisProfile& profile,
                                                        const kinematics::MachineModel& machine,
                                                        const CancelToken* cancel) {
    auto t2 = convergedTimeOptimal(profile, machine, {.cancel = cancel});
    return t2 ? std::optional<ConvergedTime>(*t2) : std::nullopt;
}

std::optional<double> timeOptimalSeconds(const AxisProfile& profile,
                                         const kinematics::MachineModel& machine,
                                         const CancelToken* cancel) {
    const auto t2 = convergedTimeOptimalOrNone(profile, machine, cancel);
    return t2 ? std::optional<double>(t2->time) : std::nullopt;
}

} // namespace bladeaxis::analysis

#include "core/analysis/derivatives.h"

#include "core/analysis/controller_filter.h"
#include "core/base/parallel.h"
#include "core/geometry/cubic_spline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace bladeaxis::analysis {

namespace {

// Slope at x of the parabola through three points (Lagrange form): the one-sided end formula
// of the 3-point scheme, exact for quadratics like the interior one.
double parabolaSlope(const double* x, const double* y, double at) {
    const double l0 = ((at - x[1]) + (at - x[2])) / ((x[0] - x[1]) * (x[0] - x[2]));
    const double l1 = ((at - x[0]) + (at - x[2])) / ((x[1] - x[0]) * (x[1] - x[2]));
    const double l2 = ((at - x[0]) + (at - x[1])) / ((x[2] - x[0]) * (x[2] - x[1]));
    return y[0] * l0 + y[1] * l1 + y[2] * l2;
}

// q'_i by the 3-point non-uniform formula of spec §8.1, one-sided parabolas at the ends.
void firstDifference(std::span<const double> s, std::span<const double> q,
                     std::vector<double>& out) {
    const std::size_t n = s.size();
    out.assign(n, 0.0);
    if (n == 2) {
        out[0] = out[1] = (q[1] - q[0]) / (s[1] - s[0]);
    }
    if (n < 3) {
        return;
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double hm = s[i] - s[i - 1];
        const double hp = s[i + 1] - s[i];
        out[i] =
            (hm * hm * (q[i + 1] - q[i]) + hp * hp * (q[i] - q[i - 1])) / (hm * hp * (hm + hp));
    }
    out[0] = parabolaSlope(&s[0], &q[0], s[0]);
    out[n - 1] = parabolaSlope(&s[n - 3], &q[n - 3], s[n - 1]);
}

// q''_i by the 3-point formula; the parabola of the end triple has the same constant second
// derivative at its end point, so the ends copy their neighbours.
void secondDifference(std::span<const double> s, std::span<const double> q,
                      std::vector<double>& out) {
    const std::size_t n = s.size();
    out.assign(n, 0.0);
    if (n < 3) {
        return;
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double hm = s[i] - s[i - 1];
        const double hp = s[i + 1] - s[i];
        out[i] = 2.0 * (hm * (q[i + 1] - q[i]) - hp * (q[i] - q[i - 1])) / (hm * hp * (hm + hp));
    }
    out[0] = out[1];
    out[n - 1] = out[n - 2];
}

void scale(std::vector<double>& values, double factor) {
    for (double& v : values) {
        v *= factor;
    }
}

// The largest |v|, NaN ignored. std::max keeps the running peak against NaN and the magnitudes
// have no -0, so the order of the comparisons does not change the result: four running peaks
// side by side hide the latency of each comparison.
double maxAbs(std::span<const double> values) {
    constexpr std::size_t kLanes = 4;
    std::array<double, kLanes> peaks{};
    std::size_t i = 0;
    for (; i + kLanes <= values.size(); i += kLanes) {
        for (std::size_t lane = 0; lane < kLanes; ++lane) {
            peaks[lane] = std::max(peaks[lane], std::abs(values[i + lane]));
        }
    }
    for (; i < values.size(); ++i) {
        peaks[0] = std::max(peaks[0], std::abs(values[i]));
    }
    return std::max(std::max(peaks[0], peaks[1]), std::max(peaks[2], peaks[3]));
}

// The percentile of |velocity| and |acceleration| an AxisSeries reports.
constexpr double kReportedQuantile = 0.999;

// Peaks and percentiles of the stored samples (the spline takes them while making the samples).
// The jerk's peak is taken by the method, which does not keep the jerk at every sample.
void takeSampleFigures(AxisSeries& series) {
    series.peakVelocity = maxAbs(series.velocity);
    series.peakAcceleration = maxAbs(series.acceleration);
    series.p999Velocity = absPercentile(series.velocity, kReportedQuantile);
    series.p999Acceleration = absPercentile(series.acceleration, kReportedQuantile);
}

void finiteDifferences(std::span<const double> s, std::span<const double> position, double feed,
                       AxisSeries& series) {
    firstDifference(s, position, series.velocity);
    secondDifference(s, position, series.acceleration);
    // The raw third difference: the 3-point slope of q'' (still exact, zero, for quadratics).
    std::vector<double> jerk;
    firstDifference(s, series.acceleration, jerk);
    scale(series.velocity, feed);
    scale(series.acceleration, feed * feed);
    scale(jerk, feed * feed * feed);
    takeSampleFigures(series);
    series.peakJerk = maxAbs(jerk);
}

Status validateKnots(std::span<const std::size_t> knots, std::size_t n) {
    const bool valid = knots.size() >= std::min<std::size_t>(n, 2) && knots.front() == 0 &&
                       knots.back() == n - 1 && std::ranges::is_sorted(knots) &&
                       std::ranges::adjacent_find(knots) == knots.end();
    if (!valid) {
        return makeError(ErrorCode::InvalidArgument,
                         "spline knots must be ascending sample indices from the first sample to "
                         "the last");
    }
    return {};
}

// The filter resamples the whole pass every millisecond: its memory follows the cycle time, not
// the program's size, so a 10-block program with one far-off point would take gigabytes.
Status checkFilterLength(std::span<const double> s, double feed) {
    constexpr double kStep = 1e-3;
    const double samples = (s.back() - s.front()) / feed / kStep;
    if (samples <= static_cast<double>(kMaxFilterSamples)) {
        return {};
    }
    const auto hours = [](double count) {
        return std::to_string(static_cast<long long>(std::llround(count * kStep / 3600.0)));
    };
    return makeError(
        ErrorCode::Geometry,
        "the controller filter would resample " + hours(samples) + " h of motion (" +
            std::to_string(static_cast<long long>(std::llround(samples / 1e6))) +
            " million 1 ms samples at the feed), more than its limit of " +
            std::to_string(kMaxFilterSamples / 1'000'000) + " million (" +
            hours(static_cast<double>(kMaxFilterSamples)) +
            " h): check the program for a far-off point or a very low feed, or use the spline "
            "derivatives (--derivatives spline; \"derivatives\": \"spline\" in a job file)");
}

// The controller-like filter (the default method, docs/figures.md): the axis at constant feed
// every millisecond, smoothed by the window twice. Velocity, acceleration and jerk are central
// differences of the smoothed positions (an end repeats its neighbour, as filterAxis's), taken
// where they are read rather than kept: per millisecond of the pass only the positions are held
// (smoothed in place). Peaks and 99.9th percentiles are taken over the whole millisecond
// series, so that they weigh the pass by time and not by how densely the post placed its points;
// the values at the samples are interpolated at their times (for T2, the layers, axes.csv).
namespace {

// Velocity, acceleration and jerk of a series stepped by `step` (central differences; an end
// repeats its neighbour), each value computed once: the peaks' loop reads each velocity and
// acceleration at up to three neighbouring steps, and recomputing them (seven velocities and
// three accelerations per step) was most of the filter's time. A small cache by index gives the
// same values, with the same bits, as computing them afresh.
class CentralDifferences {
  public:
    CentralDifferences(std::span<const double> p, double step)
        : m_p(p), m_last(static_cast<std::ptrdiff_t>(p.size()) - 2), m_twoSteps(2.0 * step) {}

    double velocity(std::ptrdiff_t k) {
        const std::ptrdiff_t i = inner(k);
        return cached(m_velocity, i, [this, i] {
            const auto u = static_cast<std::size_t>(i);
            return (m_p[u + 1] - m_p[u - 1]) / m_twoSteps;
        });
    }
    double acceleration(std::ptrdiff_t k) {
        const std::ptrdiff_t i = inner(k);
        return cached(m_acceleration, i,
                      [this, i] { return (velocity(i + 1) - velocity(i - 1)) / m_twoSteps; });
    }
    double jerk(std::ptrdiff_t k) {
        const std::ptrdiff_t i = inner(k);
        return (acceleration(i + 1) - acceleration(i - 1)) / m_twoSteps;
    }

  private:
    struct Entry {
        std::ptrdiff_t index = -1;
        double value = 0.0;
    };
    using Cache = std::array<Entry, 8>;

    std::ptrdiff_t inner(std::ptrdiff_t k) const {
        return std::clamp<std::ptrdiff_t>(k, 1, m_last);
    }

    template <class Compute>
    static double cached(Cache& cache, std::ptrdiff_t i, Compute&& compute) {
        Entry& entry = cache[static_cast<std::size_t>(i) % cache.size()];
        if (entry.index != i) {
            entry = {i, compute()};
        }
        return entry.value;
    }

    std::span<const double> m_p;
    std::ptrdiff_t m_last; // the last index with two neighbours
    double m_twoSteps;
    Cache m_velocity, m_acceleration;
};

} // namespace

// False, with `series` unfinished, when `cancel` was set on the way: it is looked at between the
// smoothing passes and every kIterationsPerCancelPoll milliseconds of the loops (tens of
// millions of them on a large program, about a second per axis).
bool filteredDerivatives(std::span<const double> s, std::span<const double> position, double feed,
                         double filterSeconds, AxisSeries& series, const CancelToken* cancel) {
    constexpr double kStep = 1e-3;
    std::vector<double> p;
    if (!smoothedPositions(s, position, feed, filterSeconds, kStep, p, cancel) ||
        isCancelled(cancel)) {
        return false;
    }
    const std::size_t m = p.size();
    CentralDifferences differences(p, kStep);
    const auto velocity = [&](std::ptrdiff_t k) { return differences.velocity(k); };
    const auto acceleration = [&](std::ptrdiff_t k) { return differences.acceleration(k); };
    const auto jerk = [&](std::ptrdiff_t k) { return differences.jerk(k); };
    const std::size_t n = s.size();
    series.velocity.assign(n, 0.0);
    series.acceleration.assign(n, 0.0);
    if (m < 3) {
        return true; // no differences on fewer than three steps (filterAxis's zeros)
    }
    AbsPercentile velocityQuantile(m, kReportedQuantile);
    AbsPercentile accelerationQuantile(m, kReportedQuantile);
    double peakVelocity = 0.0, peakAcceleration = 0.0, peakJerk = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
        if (isCancelledAt(cancel, k)) {
            return false;
        }
        const auto i = static_cast<std::ptrdiff_t>(k);
        const double v = velocity(i), a = acceleration(i), j = jerk(i);
        peakVelocity = std::max(peakVelocity, std::abs(v));
        peakAcceleration = std::max(peakAcceleration, std::abs(a));
        peakJerk = std::max(peakJerk, std::abs(j));
        velocityQuantile.add(v);
        accelerationQuantile.add(a);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (isCancelledAt(cancel, i)) {
            return false;
        }
        const double at =
            std::clamp((s[i] - s.front()) / feed / kStep, 0.0, static_cast<double>(m - 1));
        const auto k = std::min(static_cast<std::size_t>(at), m - 1);
        const auto ki = static_cast<std::ptrdiff_t>(k);
        const double f = at - static_cast<double>(k);
        const bool last = k + 1 >= m;
        series.velocity[i] =
            last ? velocity(ki) : velocity(ki) + f * (velocity(ki + 1) - velocity(ki));
        series.acceleration[i] =
            last ? acceleration(ki)
                 : acceleration(ki) + f * (acceleration(ki + 1) - acceleration(ki));
    }
    series.peakVelocity = peakVelocity;
    series.peakAcceleration = peakAcceleration;
    series.peakJerk = peakJerk;
    series.p999Velocity = velocityQuantile.value();
    series.p999Acceleration = accelerationQuantile.value();
    return true;
}

// The knots of the derivative spline: ascending sample indices, or every sample (`indices`
// empty), when the knot values are the samples themselves and need no gathering.
struct SplineKnots {
    std::span<const std::size_t> indices;
    std::size_t sampleCount = 0;

    bool everySample() const { return indices.empty(); }
    std::size_t count() const { return everySample() ? sampleCount : indices.size(); }
    std::size_t sample(std::size_t knot) const { return everySample() ? knot : indices[knot]; }

    // The values at the knots: the samples themselves, or a gathered copy kept in `storage`.
    std::span<const double> valuesAtKnots(std::span<const double> samples,
                                          std::vector<double>& storage) const {
        if (everySample()) {
            return samples;
        }
        storage.resize(indices.size());
        for (std::size_t k = 0; k < indices.size(); ++k) {
            storage[k] = samples[indices[k]];
        }
        return storage;
    }
};

// The largest |q'| at 4 interior points of an interval (q'' is linear and q''' constant per
// interval, so only the velocity can peak between the samples).
double interiorSpeed(const geometry::CubicSplineInterval& piece) {
    double peak = 0.0;
    for (int k = 1; k <= 4; ++k) {
        const double x = piece.left + 0.2 * k * piece.width();
        peak = std::max(peak, std::abs(piece.firstDerivative(x)));
    }
    return peak;
}

// One axis looks at the token between its steps and every kIterationsPerCancelPoll samples of
// its sampling, so that a cancelled job does not wait for the rest of an axis (about 0.15 s at
// five million samples); a cancelled axis holds cancelledError() (progress.h).

// Velocity, acceleration and jerk at every sample from the spline with the given knot values and
// moments (a merged sample lies inside the interval that starts at the knot before it). Peaks
// and percentiles are taken as the values are made rather than by reading the series back. The
// peak velocity also looks at 4 interior points per interval; they cost two divisions each, the
// most of the evaluation, so an interval whose bound does not exceed the peak so far, and so
// cannot raise it, is passed over.
// `velocityStorage`, when given, holds s.size() values that become the velocities, written
// over: the axis's positions, which knotQ may be (every sample a knot). Sample k's velocity is
// written once interval k has read its end values, and the last interval is taken before any,
// so a position is never read after its sample's velocity replaced it.
// False, with `series` unfinished, when `cancel` was set on the way.
bool sampleSpline(std::span<const double> s, const SplineKnots& knots,
                  std::span<const double> knotS, std::span<const double> knotQ,
                  std::span<const double> moments, double feed, AxisSeries& series,
                  std::vector<double>* velocityStorage, const CancelToken* cancel) {
    const double feed2 = feed * feed;
    const double feed3 = feed2 * feed;
    const auto interval = [&](std::size_t k) {
        return geometry::CubicSplineInterval{knotS[k],     knotS[k + 1], knotQ[k],
                                             knotQ[k + 1], moments[k],   moments[k + 1]};
    };
    const std::size_t last = knots.count() - 1;
    const geometry::CubicSplineInterval lastPiece = interval(last - 1);
    if (velocityStorage != nullptr) {
        series.velocity = std::move(*velocityStorage);
    }
    series.velocity.resize(s.size());
    series.acceleration.resize(s.size());
    double peakVelocity = 0.0, peakAcceleration = 0.0, peakJerk = 0.0;
    AbsPercentile velocityQuantile(s.size(), kReportedQuantile);
    AbsPercentile accelerationQuantile(s.size(), kReportedQuantile);
    const auto store = [&](std::size_t i, double velocity, double acceleration, double jerk) {
        series.velocity[i] = velocity * feed;
        series.acceleration[i] = acceleration * feed2;
        peakVelocity = std::max(peakVelocity, std::abs(series.velocity[i]));
        peakAcceleration = std::max(peakAcceleration, std::abs(series.acceleration[i]));
        peakJerk = std::max(peakJerk, std::abs(jerk * feed3));
        velocityQuantile.add(series.velocity[i]);
        accelerationQuantile.add(series.acceleration[i]);
    };
    double interiorPeak = 0.0;
    std::size_t nextPoll = kIterationsPerCancelPoll;
    for (std::size_t k = 0; k < last; ++k) {
        const geometry::CubicSplineInterval piece = interval(k);
        const std::size_t first = knots.sample(k);
        if (first >= nextPoll) {
            if (isCancelled(cancel)) {
                return false;
            }
            nextPoll = first + kIterationsPerCancelPoll;
        }
        store(first, piece.firstDerivative(piece.left), piece.leftMoment, piece.thirdDerivative());
        for (std::size_t i = first + 1; i < knots.sample(k + 1); ++i) {
            store(i, piece.firstDerivative(s[i]), piece.secondDerivative(s[i]),
                  piece.thirdDerivative());
        }
        // Rounding is monotonic: |q'| <= bound at the interior points stays so times the feed.
        if (!(piece.firstDerivativeBound() * feed <= peakVelocity)) {
            interiorPeak = std::max(interiorPeak, interiorSpeed(piece));
        }
    }
    store(s.size() - 1, lastPiece.firstDerivative(lastPiece.right), lastPiece.rightMoment,
          lastPiece.thirdDerivative());
    series.peakVelocity = std::max(peakVelocity, interiorPeak * feed);
    series.peakAcceleration = peakAcceleration;
    series.peakJerk = peakJerk;
    series.p999Velocity = velocityQuantile.value();
    series.p999Acceleration = accelerationQuantile.value();
    return true;
}

// Calls body(k) for every series k, each series on one thread and up to the context's thread count
// at once: a series' values never depend on how many threads there are.
template <class Body>
void forEachSeries(std::size_t series, std::size_t samples, Body&& body) {
    forEachItem(series, series * samples, std::forward<Body>(body));
}

// The first sample at which the path parameter is unusable (not finite, or not above the one
// before it); s.size() when there is none. Checked once for all axes over the same samples.
std::size_t firstBadPathSample(std::span<const double> s) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!std::isfinite(s[i]) || (i > 0 && !(s[i] > s[i - 1]))) {
            return i;
        }
    }
    return s.size();
}

// The samples of one axis; badPath is firstBadPathSample(s). The error names the first bad
// sample, a non-finite value before an out-of-order path parameter.
Status validate(std::span<const double> s, std::span<const double> position, double feed,
                std::size_t badPath) {
    if (s.size() != position.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "axis samples: " + std::to_string(s.size()) + " path values but " +
                             std::to_string(position.size()) + " positions");
    }
    if (!(feed > 0.0) || !std::isfinite(feed)) {
        return makeError(ErrorCode::InvalidArgument,
                         "feed must be positive and finite, got " + std::to_string(feed));
    }
    const auto badPosition = static_cast<std::size_t>(
        std::ranges::find_if(position, [](double q) { return !std::isfinite(q); }) -
        position.begin());
    const std::size_t bad = std::min(badPath, badPosition);
    if (bad == s.size()) {
        return {};
    }
    if (!std::isfinite(s[bad]) || !std::isfinite(position[bad])) {
        return makeError(ErrorCode::Geometry,
                         "non-finite path value or position at sample " + std::to_string(bad));
    }
    return makeError(ErrorCode::InvalidArgument,
                     "path parameter not strictly increasing at sample " + std::to_string(bad));
}

bool isStill(std::span<const double> position) {
    return std::ranges::all_of(position, [&](double q) { return q == position.front(); });
}

Status checkFinite(const AxisSeries& series) {
    if (!std::isfinite(series.peakVelocity + series.peakAcceleration + series.peakJerk)) {
        return makeError(ErrorCode::Geometry, "axis derivatives overflow (samples too close for "
                                              "the jumps between them)");
    }
    return {};
}

// What every axis of one differentiation shares, made once before the axes: the samples, the
// method and, for the spline methods, the knots and the eliminated spline system. Holds views of
// its own storage, so it stays where it is made.
class SharedFit {
  public:
    SharedFit(std::span<const double> samples, double feedRate, DerivativeMethod fitMethod,
              double windowSeconds, std::span<const std::size_t> knotIndices,
              const CancelToken* cancelToken)
        : s(samples), feed(feedRate), method(fitMethod), filterSeconds(windowSeconds),
          cancel(cancelToken), badPath(firstBadPathSample(samples)), knots{{}, samples.size()} {
        if (method == DerivativeMethod::Filtered || method == DerivativeMethod::FiniteDifference ||
            s.size() < 2 || badPath < s.size()) {
            return; // a series of fewer than 2 samples is still; a bad path fails every series
        }
        if (!knotIndices.empty() && method == DerivativeMethod::Spline) {
            knotsValid = validateKnots(knotIndices, s.size());
            if (!knotsValid) {
                return;
            }
            // Valid knots are ascending and unique from the first sample to the last: as many
            // of them as samples are every sample.
            if (knotIndices.size() < s.size()) {
                knots.indices = knotIndices;
            }
        }
        knotS = knots.valuesAtKnots(s, gatheredS);
        system.emplace(knotS);
    }
    SharedFit(const SharedFit&) = delete;
    SharedFit& operator=(const SharedFit&) = delete;

    const std::span<const double> s;
    const double feed;
    const DerivativeMethod method;
    const double filterSeconds;
    const CancelToken* const cancel;                // may be null
    const std::size_t badPath;                      // firstBadPathSample(s)
    Status knotsValid;                              // bad spline knots fail every moving axis
    SplineKnots knots;                              // of the spline methods
    std::span<const double> knotS;                  // s at the knots
    std::optional<geometry::NotAKnotSystem> system; // the spline methods, on valid samples

  private:
    std::vector<double> gatheredS;
};

// The spline derivatives of one axis: its values at the knots, their moments by the shared
// system, and the samples. Only this axis's moments (and knot values, when the knots are not
// every sample) are held meanwhile. Cancelled when the fit's token is set before the solve,
// after it or during the sampling.
Status splineDerivatives(const SharedFit& fit, std::span<const double> position, AxisSeries& series,
                         std::vector<double>* positionStorage) {
    std::vector<double> gatheredQ;
    const std::span<const double> knotQ = fit.knots.valuesAtKnots(position, gatheredQ);
    if (isCancelled(fit.cancel)) {
        return std::unexpected(cancelledError());
    }
    // Left uninitialised: the solve writes each entry.
    const auto momentBlock = std::make_unique_for_overwrite<double[]>(knotQ.size());
    const std::span<double> moments(momentBlock.get(), knotQ.size());
    fit.system->solve(knotQ, moments);
    if (isCancelled(fit.cancel) || !sampleSpline(fit.s, fit.knots, fit.knotS, knotQ, moments,
                                                 fit.feed, series, positionStorage, fit.cancel)) {
        return std::unexpected(cancelledError());
    }
    return {};
}

// One axis: validated, its range taken, and unless it is still its derivatives and peaks by the
// fit's method.
// `positionStorage`, when given, is the vector the positions occupy, which the spline methods
// take over for the velocities: 8 bytes per sample fewer on each thread of a differentiation.
Result<AxisSeries> differentiateOne(const SharedFit& fit, std::span<const double> position,
                                    std::vector<double>* positionStorage) {
    if (Status ok = validate(fit.s, position, fit.feed, fit.badPath); !ok) {
        return std::unexpected(std::move(ok.error()));
    }
    AxisSeries series;
    if (!position.empty()) {
        const auto [low, high] = std::ranges::minmax(position);
        series.minPosition = low;
        series.maxPosition = high;
    }
    if (isStill(position)) {
        // A still axis (B in four-axis work) has exactly zero derivatives by either method:
        // skip the fit, which is most of the cost per axis, and keep no zeros.
        return series;
    }
    if (!fit.knotsValid) {
        return std::unexpected(fit.knotsValid.error());
    }
    switch (fit.method) {
    case DerivativeMethod::Filtered:
        if (Status bounded = checkFilterLength(fit.s, fit.feed); !bounded) {
            return std::unexpected(std::move(bounded.error()));
        }
        if (!filteredDerivatives(fit.s, position, fit.feed, fit.filterSeconds, series,
                                 fit.cancel)) {
            return std::unexpected(cancelledError());
        }
        break;
    case DerivativeMethod::FiniteDifference:
        finiteDifferences(fit.s, position, fit.feed, series);
        break;
    case DerivativeMethod::Spline:
    case DerivativeMethod::RawSpline:
        if (Status sampled = splineDerivatives(fit, position, series, positionStorage); !sampled) {
            return std::unexpected(std::move(sampled.error()));
        }
        break;
    }
    if (Status finite = checkFinite(series); !finite) {
        return std::unexpected(std::move(finite.error()));
    }
    return series;
}

// The axes differentiated at once: every thread of the context, or one when the controller
// filter's series of that many axes (8 bytes per millisecond of the pass each) would pass the
// caller's budget.
unsigned seriesThreads(std::span<const double> s, std::size_t axes, double feed,
                       DerivativeMethod method, double seriesBytesAtOnce) {
    const unsigned threads = resolveThreadCount(currentThreadCount());
    if (method != DerivativeMethod::Filtered || !(seriesBytesAtOnce > 0.0) || s.size() < 2 ||
        !(feed > 0.0)) {
        return threads;
    }
    const double milliseconds = (s.back() - s.front()) / feed / 1e-3;
    const double atOnce = static_cast<double>(std::min<std::size_t>(threads, axes));
    return 8.0 * milliseconds * atOnce > seriesBytesAtOnce ? 1U : threads;
}

} // namespace

std::vector<Result<AxisSeries>> differentiateAxes(std::span<const double> s, std::size_t axes,
                                                  const PositionsOf& positionsOf, double feed,
                                                  DerivativeMethod method, double filterSeconds,
                                                  std::span<const std::size_t> knots,
                                                  const CancelToken* cancel,
                                                  double filterSeriesBytesAtOnce) {
    const SharedFit fit(s, feed, method, filterSeconds, knots, cancel);
    std::vector<Result<AxisSeries>> results(axes);
    const ThreadCountScope threads(seriesThreads(s, axes, feed, method, filterSeriesBytesAtOnce));
    forEachSeries(axes, s.size(), [&](std::size_t k) {
        if (isCancelled(cancel)) {
            results[k] = std::unexpected(cancelledError());
            return;
        }
        std::vector<double> scratch;
        const std::span<const double> position = positionsOf(k, scratch);
        if (isCancelled(cancel)) { // the positions may have been computed for the call
            results[k] = std::unexpected(cancelledError());
            return;
        }
        const bool inScratch =
            position.data() == scratch.data() && position.size() == scratch.size();
        results[k] = differentiateOne(fit, position, inScratch ? &scratch : nullptr);
    });
    return results;
}

std::vector<Result<AxisSeries>> differentiateAxes(std::span<const double> s,
                                                  std::span<const std::vector<double>> positions,
                                                  double feed, DerivativeMethod method,
                                                  double filterSeconds,
                                                  std::span<const std::size_t> knots) {
    const PositionsOf given = [&](std::size_t k, std::vector<double>&) {
        return std::span<const double>(positions[k]);
    };
    return differentiateAxes(s, positions.size(), given, feed, method, filterSeconds, knots);
}

Result<AxisSeries> differentiateAxis(std::span<const double> s, std::vector<double> position,
                                     double feed, DerivativeMethod method, double filterSeconds,
                                     std::span<const std::size_t> knots) {
    const std::vector<std::vector<double>> positions{std::move(position)};
    return std::move(differentiateAxes(s, positions, feed, method, filterSeconds, knots).front());
}

AbsPercentile::AbsPercentile(std::size_t count, double p) {
    if (count == 0 || !(p >= 0.0)) {
        m_smallestKept = HUGE_VAL; // nothing to rank: value() is 0
        return;
    }
    const double position = std::min(p, 1.0) * static_cast<double>(count - 1);
    const auto k = static_cast<std::size_t>(position);
    m_fraction = position - static_cast<double>(k);
    m_keep = count - k;
    m_kept.reserve(m_keep);
}

void AbsPercentile::keep(double v) {
    if (m_keep == 0) {
        return; // no values to rank (a NaN still fails the test in add)
    }
    const double magnitude = std::isnan(v) ? HUGE_VAL : std::abs(v);
    const std::ranges::greater smallestOnTop;
    if (m_kept.size() < m_keep) {
        m_kept.push_back(magnitude);
        std::ranges::push_heap(m_kept, smallestOnTop);
    } else if (magnitude > m_kept.front()) {
        std::ranges::pop_heap(m_kept, smallestOnTop);
        m_kept.back() = magnitude;
        std::ranges::push_heap(m_kept, smallestOnTop);
    }
    if (m_kept.size() == m_keep) {
        m_smallestKept = m_kept.front();
    }
}

double AbsPercentile::value() const {
    if (m_kept.empty()) {
        return 0.0;
    }
    const double lower = m_kept.front();
    if (m_fraction == 0.0 || m_kept.size() < 2) {
        return lower;
    }
    // The next larger magnitude is one of the two children of the heap's top.
    const double upper = m_kept.size() == 2 ? m_kept[1] : std::min(m_kept[1], m_kept[2]);
    return lower + m_fraction * (upper - lower);
}

double absPercentile(std::span<const double> values, double p) {
    AbsPercentile quantile(values.size(), p);
    for (double v : values) {
        quantile.add(v);
    }
    return quantile.value();
}

} // namespace bladeaxis::analysis

#include "core/analysis/derivatives.h"

#include "core/analysis/controller_filter.h"
#include "core/geometry/cubic_spline.h"

#include <algorithm>
#include <cmath>
#include <string>

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

double maxAbs(std::span<const double> values) {
    double peak = 0.0;
    for (double v : values) {
        peak = std::max(peak, std::abs(v));
    }
    return peak;
}

void finiteDifferences(std::span<const double> s, double feed, AxisSeries& series) {
    firstDifference(s, series.position, series.velocity);
    secondDifference(s, series.position, series.acceleration);
    // The raw third difference: the 3-point slope of q'' (still exact, zero, for quadratics).
    firstDifference(s, series.acceleration, series.jerk);
    scale(series.velocity, feed);
    scale(series.acceleration, feed * feed);
    scale(series.jerk, feed * feed * feed);
}

// Returns the largest |velocity| found at the 4 interior points of the intervals.
Status splineDerivatives(std::span<const double> s, double feed, AxisSeries& series,
                         double& interiorPeak, std::span<const std::size_t> knots) {
    const std::size_t n = s.size();
    series.velocity.assign(n, 0.0);
    series.acceleration.assign(n, 0.0);
    series.jerk.assign(n, 0.0);
    interiorPeak = 0.0;
    if (n < 2) {
        return {};
    }
    std::vector<double> knotS, knotQ;
    knotS.reserve(knots.size());
    knotQ.reserve(knots.size());
    for (const std::size_t k : knots) {
        knotS.push_back(s[k]);
        knotQ.push_back(series.position[k]);
    }
    const geometry::CubicSpline spline(knotS, knotQ);
    if (!spline.isValid()) {
        return makeError(ErrorCode::Internal, "axis spline rejected validated samples");
    }
    const double feed2 = feed * feed;
    const double feed3 = feed2 * feed;
    std::size_t knot = 0; // the knot at or before sample i
    for (std::size_t i = 0; i < n; ++i) {
        while (knot + 1 < knots.size() && knots[knot + 1] <= i) {
            ++knot;
        }
        if (knots[knot] == i) {
            series.velocity[i] = spline.firstDerivativeAtKnot(knot) * feed;
            series.acceleration[i] = spline.secondDerivativeAtKnot(knot) * feed2;
            series.jerk[i] = spline.thirdDerivativeAtKnot(knot) * feed3;
            continue;
        }
        // A merged sample lies inside the interval that starts at the knot before it.
        series.velocity[i] = spline.firstDerivative(knot, s[i]) * feed;
        series.acceleration[i] = spline.secondDerivative(knot, s[i]) * feed2;
        series.jerk[i] = spline.thirdDerivative(knot) * feed3;
    }
    for (std::size_t i = 0; i + 1 < knotS.size(); ++i) {
        const double h = knotS[i + 1] - knotS[i];
        for (int k = 1; k <= 4; ++k) {
            const double x = knotS[i] + 0.2 * k * h;
            interiorPeak = std::max(interiorPeak, std::abs(spline.firstDerivative(i, x)));
        }
    }
    interiorPeak *= feed;
    return {};
}

// Every sample's index: the knots of the raw spline.
std::vector<std::size_t> allSamples(std::size_t n) {
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) {
        all[i] = i;
    }
    return all;
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

struct Peaks {
    double velocity = 0.0, acceleration = 0.0, jerk = 0.0;
};

Peaks filteredDerivatives(std::span<const double> s, double feed, double filterSeconds,
                          AxisSeries& series) {
    const FilteredAxis filtered = filterAxis(s, series.position, feed, filterSeconds);
    const std::size_t n = s.size();
    series.velocity.resize(n);
    series.acceleration.resize(n);
    series.jerk.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = (s[i] - s.front()) / feed;
        series.velocity[i] = sampleAt(filtered.velocity, filtered.step, t);
        series.acceleration[i] = sampleAt(filtered.acceleration, filtered.step, t);
        series.jerk[i] = sampleAt(filtered.jerk, filtered.step, t);
    }
    return {maxAbs(filtered.velocity), maxAbs(filtered.acceleration), maxAbs(filtered.jerk)};
}

Status validate(std::span<const double> s, std::span<const double> position, double feed) {
    if (s.size() != position.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "axis samples: " + std::to_string(s.size()) + " path values but " +
                             std::to_string(position.size()) + " positions");
    }
    if (!(feed > 0.0) || !std::isfinite(feed)) {
        return makeError(ErrorCode::InvalidArgument,
                         "feed must be positive and finite, got " + std::to_string(feed));
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!std::isfinite(s[i]) || !std::isfinite(position[i])) {
            return makeError(ErrorCode::Geometry,
                             "non-finite path value or position at sample " + std::to_string(i));
        }
        if (i > 0 && !(s[i] > s[i - 1])) {
            return makeError(ErrorCode::InvalidArgument,
                             "path parameter not strictly increasing at sample " +
                                 std::to_string(i));
        }
    }
    return {};
}

} // namespace

Result<AxisSeries> differentiateAxis(std::span<const double> s, std::vector<double> position,
                                     double feed, DerivativeMethod method, double filterSeconds,
                                     std::span<const std::size_t> knots) {
    if (Status ok = validate(s, position, feed); !ok) {
        return std::unexpected(std::move(ok.error()));
    }
    AxisSeries series;
    series.position = std::move(position);
    double interiorPeak = 0.0;
    const bool still = std::ranges::all_of(series.position,
                                           [&](double q) { return q == series.position.front(); });
    if (still) {
        // A still axis (B in four-axis work) has exactly zero derivatives by either method:
        // skip the fit, which is most of the cost per axis.
        const std::size_t n = series.position.size();
        series.velocity.assign(n, 0.0);
        series.acceleration.assign(n, 0.0);
        series.jerk.assign(n, 0.0);
        return series;
    }
    Peaks filteredPeaks;
    if (method == DerivativeMethod::Spline || method == DerivativeMethod::RawSpline) {
        std::vector<std::size_t> every;
        if (knots.empty() || method == DerivativeMethod::RawSpline) {
            every = allSamples(s.size());
            knots = every;
        } else if (Status ok = validateKnots(knots, s.size()); !ok) {
            return std::unexpected(std::move(ok.error()));
        }
        if (Status ok = splineDerivatives(s, feed, series, interiorPeak, knots); !ok) {
            return std::unexpected(std::move(ok.error()));
        }
    } else if (method == DerivativeMethod::Filtered) {
        filteredPeaks = filteredDerivatives(s, feed, filterSeconds, series);
    } else {
        finiteDifferences(s, feed, series);
    }
    series.peakVelocity = std::max({maxAbs(series.velocity), interiorPeak, filteredPeaks.velocity});
    series.peakAcceleration = std::max(maxAbs(series.acceleration), filteredPeaks.acceleration);
    series.peakJerk = std::max(maxAbs(series.jerk), filteredPeaks.jerk);
    series.p999Velocity = absPercentile(series.velocity, 0.999);
    series.p999Acceleration = absPercentile(series.acceleration, 0.999);
    if (!std::isfinite(series.peakVelocity + series.peakAcceleration + series.peakJerk)) {
        return makeError(ErrorCode::Geometry, "axis derivatives overflow (samples too close for "
                                              "the jumps between them)");
    }
    return series;
}

double absPercentile(std::span<const double> values, double p) {
    if (values.empty() || !(p >= 0.0)) {
        return 0.0;
    }
    const std::size_t n = values.size();
    const double position = std::min(p, 1.0) * static_cast<double>(n - 1);
    const auto k = static_cast<std::size_t>(position);
    const double fraction = position - static_cast<double>(k);
    // Only the n - k largest magnitudes matter: for p = 0.999 that is 0.1 % of the samples, so
    // a partial sort into a small buffer avoids copying (and page-faulting) the whole series.
    // NaN would break the ordering: it ranks above every number.
    const auto magnitude = [](double v) { return std::isnan(v) ? HUGE_VAL : std::abs(v); };
    std::vector<double> top(n - k);
    std::ranges::partial_sort_copy(values, top, std::ranges::greater{}, magnitude, magnitude);
    const double lower = magnitude(top.back());
    if (fraction == 0.0 || top.size() < 2) {
        return lower;
    }
    const double upper = magnitude(top[top.size() - 2]);
    return lower + fraction * (upper - lower);
}

} // namespace bladeaxis::analysis

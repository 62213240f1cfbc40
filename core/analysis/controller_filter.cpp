#include "core/analysis/controller_filter.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::analysis {

namespace {

std::vector<double> resample(std::span<const double> s, std::span<const double> position,
                             double feed, double step) {
    const double duration = (s.back() - s.front()) / feed;
    // Samples inside the path only: one past its end would repeat the end value and read as
    // the axis stopping there.
    const auto count = static_cast<std::size_t>(std::floor(duration / step)) + 1;
    std::vector<double> out(count);
    std::size_t segment = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const double at = std::min(s.front() + static_cast<double>(k) * step * feed, s.back());
        while (segment + 2 < s.size() && s[segment + 1] < at) {
            ++segment;
        }
        const double h = s[segment + 1] - s[segment];
        const double f = h > 0.0 ? std::clamp((at - s[segment]) / h, 0.0, 1.0) : 0.0;
        out[k] = position[segment] + f * (position[segment + 1] - position[segment]);
    }
    return out;
}

// Central differences on a uniform grid; the end values repeat their neighbours.
std::vector<double> derivative(const std::vector<double>& values, double step) {
    const std::size_t n = values.size();
    std::vector<double> out(n, 0.0);
    for (std::size_t k = 1; k + 1 < n; ++k) {
        out[k] = (values[k + 1] - values[k - 1]) / (2.0 * step);
    }
    if (n >= 3) {
        out.front() = out[1];
        out.back() = out[n - 2];
    }
    return out;
}

} // namespace

std::vector<double> movingAverage(std::span<const double> values, std::size_t width) {
    const std::size_t n = values.size();
    if (n == 0 || width <= 1) {
        return {values.begin(), values.end()};
    }
    const std::size_t half = width / 2;
    std::vector<double> prefix(n + 2 * half + 1, 0.0);
    // Outside the series the axis continues its motion: the padding is the point reflection
    // of the series about its end sample (2 q_0 - q_j), which any straight motion extends
    // exactly. Holding the end value instead would stop an axis that is moving at the start of
    // the pass dead within one window and show a start-up acceleration of about v / window that
    // the program never commands.
    const auto padded = [&](std::size_t k) {
        if (k < half) {
            const std::size_t j = std::min(half - k, n - 1);
            return 2.0 * values[0] - values[j];
        }
        if (k - half >= n) {
            const std::size_t j = std::min(k - half - (n - 1), n - 1);
            return 2.0 * values[n - 1] - values[n - 1 - j];
        }
        return values[k - half];
    };
    for (std::size_t k = 0; k < n + 2 * half; ++k) {
        prefix[k + 1] = prefix[k] + padded(k);
    }
    std::vector<double> out(n);
    const double span = static_cast<double>(2 * half + 1);
    for (std::size_t k = 0; k < n; ++k) {
        out[k] = (prefix[k + 2 * half + 1] - prefix[k]) / span;
    }
    return out;
}

double sampleAt(const std::vector<double>& series, double step, double t) {
    if (series.empty()) {
        return 0.0;
    }
    const double position = std::clamp(t / step, 0.0, static_cast<double>(series.size() - 1));
    const auto k = std::min(static_cast<std::size_t>(position), series.size() - 1);
    if (k + 1 >= series.size()) {
        return series.back();
    }
    const double f = position - static_cast<double>(k);
    return series[k] + f * (series[k + 1] - series[k]);
}

FilteredAxis filterAxis(std::span<const double> s, std::span<const double> position, double feed,
                        double windowSeconds, double step) {
    FilteredAxis axis;
    axis.step = step;
    if (s.size() < 2 || s.size() != position.size() || !(feed > 0.0) || !(step > 0.0)) {
        axis.position.assign(position.begin(), position.end());
        axis.velocity.assign(position.size(), 0.0);
        axis.acceleration.assign(position.size(), 0.0);
        axis.jerk.assign(position.size(), 0.0);
        return axis;
    }
    const auto width = static_cast<std::size_t>(std::lround(std::max(windowSeconds, 0.0) / step));
    const std::vector<double> raw = resample(s, position, feed, step);
    axis.position = movingAverage(movingAverage(raw, width), width);
    axis.velocity = derivative(axis.position, step);
    axis.acceleration = derivative(axis.velocity, step);
    axis.jerk = derivative(axis.acceleration, step);
    return axis;
}

} // namespace bladeaxis::analysis

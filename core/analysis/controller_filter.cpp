#include "core/analysis/controller_filter.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::analysis {

namespace {

// The axis at every `step` seconds of the pass at constant feed, linear between the samples, into
// `out`.
void resample(std::span<const double> s, std::span<const double> position, double feed, double step,
              std::vector<double>& out) {
    const double duration = (s.back() - s.front()) / feed;
    // Samples inside the path only: one past its end would repeat the end value and read as
    // the axis stopping there.
    const auto count = static_cast<std::size_t>(std::floor(duration / step)) + 1;
    out.resize(count);
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

namespace {

// The moving average of n values read through original(j), each output handed to
// write(k, value) in order k = 0, 1, ...; at output k, original(j) is read for j from k - half - 1
// on (and for the end samples the reflections read).
template <class Original, class Write>
void movingAverageOver(std::size_t n, std::size_t width, Original&& original, Write&& write) {
    const std::size_t half = width / 2;
    // Outside the series the axis continues its motion: the padding is the point reflection
    // of the series about its end sample (2 q_0 - q_j), which any straight motion extends
    // exactly. Holding the end value instead would stop an axis that is moving at the start of
    // the pass dead within one window and show a start-up acceleration of about v / window that
    // the program never commands.
    const auto padded = [&](std::size_t k) {
        if (k < half) {
            const std::size_t j = std::min(half - k, n - 1);
            return 2.0 * original(0) - original(j);
        }
        if (k - half >= n) {
            const std::size_t j = std::min(k - half - (n - 1), n - 1);
            return 2.0 * original(n - 1) - original(n - 1 - j);
        }
        return original(k - half);
    };
    const std::size_t span = 2 * half + 1;
    const auto windowSum = [&](std::size_t first) {
        double sum = 0.0;
        for (std::size_t j = first; j < first + span; ++j) {
            sum += padded(j);
        }
        return sum;
    };
    // A running sum, summed afresh every kFreshSum outputs so that its rounding cannot drift:
    // a prefix sum over a long pass reached 1e9 for a turning A and lost 1e-7 rad to rounding,
    // about 1 deg/s^2 once differentiated twice at 1 ms.
    constexpr std::size_t kFreshSum = 256;
    double sum = windowSum(0);
    write(0, sum / static_cast<double>(span));
    for (std::size_t k = 1; k < n; ++k) {
        sum = k % kFreshSum == 0 ? windowSum(k) : sum + (padded(k + span - 1) - padded(k - 1));
        write(k, sum / static_cast<double>(span));
    }
}

} // namespace

void movingAverageInto(std::span<const double> values, std::size_t width,
                       std::vector<double>& out) {
    const std::size_t n = values.size();
    out.resize(n);
    if (n == 0 || width <= 1) {
        std::copy(values.begin(), values.end(), out.begin());
        return;
    }
    movingAverageOver(
        n, width, [values](std::size_t j) { return values[j]; },
        [&out](std::size_t k, double value) { out[k] = value; });
}

void movingAverageInPlace(std::vector<double>& values, std::size_t width) {
    const std::size_t n = values.size();
    if (n == 0 || width <= 1) {
        return;
    }
    // An output overwrites its own input, which later outputs still read for up to a window
    // behind (and the first sample, the start's reflection centre): the overwritten inputs are
    // kept in a ring of two windows, so the series needs no second copy (8 bytes per
    // millisecond of the pass and axis).
    const std::size_t ring = 2 * (width / 2 + 1) + 2;
    std::vector<double> behind(ring);
    const double first = values[0];
    std::size_t written = 0; // outputs [0, written) are in `values`
    movingAverageOver(
        n, width,
        [&](std::size_t j) {
            if (j >= written) {
                return values[j];
            }
            return j == 0 ? first : behind[j % ring];
        },
        [&](std::size_t k, double value) {
            behind[k % ring] = values[k];
            values[k] = value;
            written = k + 1;
        });
}

std::vector<double> movingAverage(std::span<const double> values, std::size_t width) {
    std::vector<double> out;
    movingAverageInto(values, width, out);
    return out;
}

bool smoothedPositions(std::span<const double> s, std::span<const double> position, double feed,
                       double windowSeconds, double step, std::vector<double>& out,
                       const CancelToken* cancel) {
    const auto width = static_cast<std::size_t>(std::lround(std::max(windowSeconds, 0.0) / step));
    resample(s, position, feed, step, out);
    for (int pass = 0; pass < 2; ++pass) {
        if (isCancelled(cancel)) {
            return false;
        }
        movingAverageInPlace(out, width);
    }
    return true;
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
    smoothedPositions(s, position, feed, windowSeconds, step, axis.position);
    axis.velocity = derivative(axis.position, step);
    axis.acceleration = derivative(axis.velocity, step);
    axis.jerk = derivative(axis.acceleration, step);
    return axis;
}

} // namespace bladeaxis::analysis

#include "core/compare/channel_metrics.h"

#include "core/geometry/angles.h"
#include "core/optimal/layer_optimum.h"
#include "core/scheduling/plane_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bladeaxis::compare {

std::vector<double> secondDerivative(std::span<const double> s, std::span<const double> theta) {
    const std::size_t n = std::min(s.size(), theta.size());
    std::vector<double> second(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double before = s[i] - s[i - 1], after = s[i + 1] - s[i];
        if (!(before > 0.0 && after > 0.0)) {
            continue; // merged duplicates carry no curvature information
        }
        second[i] = 2.0 * (before * (theta[i + 1] - theta[i]) - after * (theta[i] - theta[i - 1])) /
                    (before * after * (before + after));
    }
    return second;
}

namespace {

double startingBranch(const scheduling::LayerResult& layer) {
    if (!layer.thetaMin.empty() && !layer.thetaMax.empty() &&
        std::isfinite(layer.thetaMin.front() + layer.thetaMax.front())) {
        return 0.5 * (layer.thetaMin.front() + layer.thetaMax.front());
    }
    return layer.thetaOriginal.empty() ? 0.0 : layer.thetaOriginal.front();
}

} // namespace

std::vector<std::vector<double>> layerThetas(const scheduling::ScheduleResult& reference,
                                             std::span<const Vec3> axes) {
    std::vector<std::vector<double>> thetas;
    thetas.reserve(reference.layers.size());
    for (const scheduling::LayerResult& layer : reference.layers) {
        std::vector<double> theta;
        theta.reserve(layer.inputIndex.size());
        // The first sample takes the 2 pi branch nearest the channel's middle: the channel is
        // what the figures are measured against, and a schedule may lie more than half a turn
        // from the CAM orientation (starting from the original there picked the wrong branch).
        // The rest follow by continuity, so a schedule that really leaves the channel shows.
        double previous = startingBranch(layer);
        for (std::size_t index : layer.inputIndex) {
            const double absolute = scheduling::planeAngle(axes[index], reference.traversalSign);
            previous = geometry::unwrapNear(absolute - layer.junctionAngle, previous);
            theta.push_back(previous);
        }
        thetas.push_back(std::move(theta));
    }
    return thetas;
}

namespace {

void addLayer(const scheduling::LayerResult& layer, const std::vector<double>& theta,
              ChannelMetrics& metrics) {
    for (std::size_t j = 0; j < theta.size(); ++j) {
        const double clearance =
            std::min(theta[j] - layer.thetaMin[j], layer.thetaMax[j] - theta[j]);
        metrics.minClearance = std::min(metrics.minClearance, clearance);
        metrics.samplesOutside += clearance < -1e-9 ? 1 : 0;
    }
    // theta'' on the samples the optimum is solved on (optimal::problemSamples): without a
    // post's micrometre chords, whose second differences (1/h^2) would measure the split, and
    // where the optimum interpolates linearly (kinks at its kept samples), so that no feasible
    // schedule can measure better than the optimum on the optimum's own objective.
    std::vector<double> s, thetaOnGrid;
    for (std::size_t j : optimal::problemSamples(layer.s)) {
        s.push_back(layer.s[j]);
        thetaOnGrid.push_back(theta[j]);
    }
    const std::vector<double> second = secondDerivative(s, thetaOnGrid);
    for (std::size_t j = 1; j + 1 < second.size(); ++j) {
        metrics.peakSecondDerivative = std::max(metrics.peakSecondDerivative, std::abs(second[j]));
        metrics.secondDerivativeEnergy += second[j] * second[j] * 0.5 * (s[j + 1] - s[j - 1]);
    }
    int direction = 0;
    for (std::size_t j = 1; j < theta.size(); ++j) {
        const double step = theta[j] - theta[j - 1];
        if (std::abs(step) < 1e-9) {
            continue;
        }
        const int sign = step > 0.0 ? 1 : -1;
        metrics.thetaReversals += (direction != 0 && sign != direction) ? 1 : 0;
        direction = sign;
    }
}

} // namespace

ChannelMetrics measureInChannel(const scheduling::ScheduleResult& reference,
                                std::span<const Vec3> axes) {
    ChannelMetrics metrics;
    metrics.minClearance = std::numeric_limits<double>::infinity();
    const auto thetas = layerThetas(reference, axes);
    for (std::size_t k = 0; k < reference.layers.size(); ++k) {
        addLayer(reference.layers[k], thetas[k], metrics);
    }
    return metrics;
}

} // namespace bladeaxis::compare

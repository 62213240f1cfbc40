#pragma once
// The layer the S-theta editor benchmarks drag in: 5,000 samples over 500 mm, a rising S-shaped
// channel of half-width 0.3 rad, scheduled through five key points.

#include "core/scheduling/schedule.h"

#include <cmath>
#include <numbers>

namespace bladeaxis::bench {

constexpr std::size_t kSamples = 5000;
constexpr double kLayerLengthMm = 500.0;

inline double sShapedCentre(double s) {
    return 0.5 * (1.0 - std::cos(std::numbers::pi * s / kLayerLengthMm));
}

inline scheduling::LayerResult sShapedLayer() {
    scheduling::LayerResult layer;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const double s =
            kLayerLengthMm * static_cast<double>(i) / static_cast<double>(kSamples - 1);
        layer.s.push_back(s);
        layer.thetaOriginal.push_back(sShapedCentre(s));
        layer.thetaMin.push_back(sShapedCentre(s) - 0.3);
        layer.thetaMax.push_back(sShapedCentre(s) + 0.3);
    }
    layer.lo = layer.thetaMin;
    layer.hi = layer.thetaMax;
    layer.theta = layer.thetaOriginal;
    for (const std::size_t index :
         {std::size_t{0}, kSamples / 4, kSamples / 2, 3 * kSamples / 4, kSamples - 1}) {
        layer.polyline.emplace_back(layer.s[index], sShapedCentre(layer.s[index]));
    }
    layer.keyPoints = layer.polyline;
    return layer;
}

} // namespace bladeaxis::bench

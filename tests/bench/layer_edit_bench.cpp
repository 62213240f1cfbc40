// Re-smoothing one 5,000-sample layer after a key-point drag: the work the S-theta editor does
// on every mouse move (target: well under a 16 ms frame).

#include "core/scheduling/layer_edit.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using bladeaxis::Vec2;
using bladeaxis::scheduling::LayerResult;

constexpr std::size_t kSamples = 5000;
constexpr double kLengthMm = 500.0;

double centre(double s) {
    return 0.5 * (1.0 - std::cos(std::numbers::pi * s / kLengthMm));
}

// A rising S-shaped channel of half-width 0.3 rad, scheduled through five key points.
LayerResult sShapedLayer() {
    LayerResult layer;
    for (std::size_t i = 0; i < kSamples; ++i) {
        const double s = kLengthMm * static_cast<double>(i) / static_cast<double>(kSamples - 1);
        layer.s.push_back(s);
        layer.thetaOriginal.push_back(centre(s));
        layer.thetaMin.push_back(centre(s) - 0.3);
        layer.thetaMax.push_back(centre(s) + 0.3);
    }
    layer.lo = layer.thetaMin;
    layer.hi = layer.thetaMax;
    layer.theta = layer.thetaOriginal;
    for (const std::size_t index :
         {std::size_t{0}, kSamples / 4, kSamples / 2, 3 * kSamples / 4, kSamples - 1}) {
        layer.polyline.emplace_back(layer.s[index], centre(layer.s[index]));
    }
    layer.keyPoints = layer.polyline;
    return layer;
}

void resmoothAfterDrag(benchmark::State& state) {
    const LayerResult layer = sShapedLayer();
    const auto parameters = bladeaxis::scheduling::bestPreset();
    std::vector<Vec2> vertices = layer.polyline;
    double offset = 0.02;
    for (auto _ : state) {
        vertices[2].y() = layer.polyline[2].y() + offset; // the drag moves the middle key point
        offset = -offset;
        auto edited = bladeaxis::scheduling::resmoothLayer(layer, vertices, parameters);
        if (!edited) {
            state.SkipWithError(edited.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(edited->theta.data());
    }
    state.SetLabel("5000-sample layer, 5 key points");
}
BENCHMARK(resmoothAfterDrag)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

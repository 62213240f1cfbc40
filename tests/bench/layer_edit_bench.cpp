// Re-smoothing one 5,000-sample layer after a key-point drag: the work the S-theta editor does
// on every mouse move (target: well under a 16 ms frame).

#include "core/scheduling/layer_edit.h"
#include "tests/bench/s_shaped_layer.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using bladeaxis::Vec2;
using bladeaxis::scheduling::LayerResult;

using bladeaxis::bench::kSamples;
using bladeaxis::bench::sShapedLayer;

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

// Per-layer solve time of the physical-limit baseline (spec §9) on the demo blade's layers,
// next to the S-theta engine's time per layer, for the issue's "stheta-best at least 100x
// faster than optimal-qp per layer". Every benchmark solves all layers once per iteration and
// reports the mean time per layer in the counter `time_per_layer` (seconds, SI-prefixed).

#include "core/blade/presets.h"
#include "core/optimal/layer_optimum.h"
#include "core/scheduling/schedule.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>

namespace {

using namespace bladeaxis;

struct Demo {
    scheduling::ScheduleInput input;
    std::vector<optimal::LayerBounds> bounds;
};

const Demo& demo() {
    static const Demo d = [] {
        Demo result;
        auto bladeModel = blade::Blade::create(blade::demoBladeSpec());
        if (!bladeModel) {
            std::fprintf(stderr, "blade: %s\n", bladeModel.error().message.c_str());
            std::abort();
        }
        auto path = blade::generateHelicalPath(*bladeModel, blade::demoPathSpec());
        if (!path) {
            std::fprintf(stderr, "demo: %s\n", path.error().message.c_str());
            std::abort();
        }
        result.input.toolRadius = blade::demoPathSpec().toolRadius;
        result.input.centres = path->centre;
        for (const auto& record : path->path.records) {
            result.input.axes.push_back(record.axis);
        }
        auto scheduled = scheduling::schedule(result.input, scheduling::bestPreset());
        if (!scheduled) {
            std::fprintf(stderr, "schedule: %s\n", scheduled.error().message.c_str());
            std::abort();
        }
        const auto& layers = scheduled->layers;
        for (std::size_t k = 0; k < layers.size(); ++k) {
            result.bounds.push_back(optimal::boundsOf(layers[k], k == 0, k + 1 == layers.size()));
        }
        return result;
    }();
    return d;
}

void reportPerLayer(benchmark::State& state, std::size_t layers) {
    state.counters["layers"] = static_cast<double>(layers);
    state.counters["time_per_layer"] = benchmark::Counter(
        static_cast<double>(layers),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The whole engine (channel, hull, linearisation, smoothing) on the whole demo path.
void BM_EngineBestPerLayer(benchmark::State& state) {
    const Demo& d = demo();
    for (auto _ : state) {
        auto result = scheduling::schedule(d.input, scheduling::bestPreset());
        benchmark::DoNotOptimize(result);
    }
    reportPerLayer(state, d.bounds.size());
}
BENCHMARK(BM_EngineBestPerLayer)->Unit(benchmark::kMillisecond);

void BM_OptimalQpPerLayer(benchmark::State& state) {
    const Demo& d = demo();
    for (auto _ : state) {
        for (const auto& bounds : d.bounds) {
            auto layer = optimal::smoothestLayer(bounds);
            if (!layer) {
                state.SkipWithError("optimal-qp failed");
                return;
            }
            benchmark::DoNotOptimize(layer);
        }
    }
    reportPerLayer(state, d.bounds.size());
}
BENCHMARK(BM_OptimalQpPerLayer)->Unit(benchmark::kMillisecond);

void BM_OptimalLpPerLayer(benchmark::State& state) {
    const Demo& d = demo();
    for (auto _ : state) {
        for (const auto& bounds : d.bounds) {
            auto layer = optimal::minimumPeakLayer(bounds);
            if (!layer) {
                state.SkipWithError("optimal-lp failed");
                return;
            }
            benchmark::DoNotOptimize(layer);
        }
    }
    reportPerLayer(state, d.bounds.size());
}
BENCHMARK(BM_OptimalLpPerLayer)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

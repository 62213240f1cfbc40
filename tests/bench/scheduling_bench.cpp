// Scheduling throughput (issue target: >= 5 million CL points/s on one core with the best preset,
// a 1,000,000-point program well under 1 s). Inputs are generated once by core/blade; only
// scheduling::schedule is timed (no I/O).

#include "core/blade/presets.h"
#include "core/scheduling/schedule.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <optional>

namespace {

using namespace bladeaxis;

scheduling::ScheduleInput toInput(const blade::GeneratedPath& generated, double radius) {
    scheduling::ScheduleInput input;
    input.toolRadius = radius;
    input.centres = generated.centre;
    for (const toolpath::ClRecord& record : generated.path.records) {
        input.axes.push_back(record.axis);
    }
    return input;
}

scheduling::ScheduleInput generate(const blade::BladeSpec& bladeSpec,
                                   const blade::HelicalPathSpec& pathSpec) {
    auto bladeModel = blade::Blade::create(bladeSpec);
    if (!bladeModel) {
        std::fprintf(stderr, "blade: %s\n", bladeModel.error().message.c_str());
        std::abort();
    }
    auto generated = blade::generateHelicalPath(*bladeModel, pathSpec);
    if (!generated) {
        std::fprintf(stderr, "path: %s\n", generated.error().message.c_str());
        std::abort();
    }
    return toInput(*generated, pathSpec.toolRadius);
}

// The demo family: the demo blade and path (8 revolutions).
const scheduling::ScheduleInput& demoInput() {
    static const scheduling::ScheduleInput input =
        generate(blade::demoBladeSpec(), blade::demoPathSpec());
    return input;
}

// About a million points: the demo section on a long blade, many revolutions, fine tolerance.
const scheduling::ScheduleInput& millionInput() {
    static const scheduling::ScheduleInput input = [] {
        blade::BladeSpec bladeSpec = blade::demoBladeSpec();
        bladeSpec.spanEnd = 400.0;
        bladeSpec.staggerEnd = bladeSpec.staggerStart + units::degToRad(30.0);
        blade::HelicalPathSpec pathSpec = blade::demoPathSpec();
        pathSpec.pitch = 0.5;
        pathSpec.revolutions = 760;
        pathSpec.chordalTolerance = 0.002;
        pathSpec.maxStep = 0.25;
        return generate(bladeSpec, pathSpec);
    }();
    return input;
}

void runSchedule(benchmark::State& state, const scheduling::ScheduleInput& input,
                 scheduling::ScheduleParameters parameters, unsigned threads) {
    parameters.threads = threads;
    for (auto _ : state) {
        auto result = scheduling::schedule(input, parameters);
        if (!result) {
            state.SkipWithError(result.error().message.c_str());
            break;
        }
        benchmark::DoNotOptimize(result->newAxes.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(input.centres.size()));
    state.counters["points"] = static_cast<double>(input.centres.size());
}

void BM_ScheduleDemoBest(benchmark::State& state) {
    runSchedule(state, demoInput(), scheduling::bestPreset(), 1);
}
BENCHMARK(BM_ScheduleDemoBest)->Unit(benchmark::kMillisecond);

void BM_ScheduleDemoFaithful(benchmark::State& state) {
    runSchedule(state, demoInput(), scheduling::faithfulPreset(), 1);
}
BENCHMARK(BM_ScheduleDemoFaithful)->Unit(benchmark::kMillisecond);

void BM_ScheduleMillionPoints(benchmark::State& state) {
    const auto preset =
        state.range(0) == 0 ? scheduling::bestPreset() : scheduling::faithfulPreset();
    runSchedule(state, millionInput(), preset, 1);
    state.SetLabel(state.range(0) == 0 ? "best, 1 thread" : "faithful, 1 thread");
}
BENCHMARK(BM_ScheduleMillionPoints)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Layers are independent (spec §3): all hardware threads over the layers.
void BM_ScheduleMillionPointsParallel(benchmark::State& state) {
    runSchedule(state, millionInput(), scheduling::bestPreset(), 0);
    state.SetLabel("best, all threads");
}
BENCHMARK(BM_ScheduleMillionPointsParallel)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();

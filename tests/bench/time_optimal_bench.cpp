// T2 (spec §8.3) on a million-sample path: the reachability passes must stay O(n).

#include "core/analysis/axis_profile.h"
#include "core/analysis/time_optimal.h"
#include "core/kinematics/machine_model.h"
#include "tests/bench/bench_size.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace bladeaxis;

// A blade-finishing-like spiral about X: the table A turns continuously while X advances
// 0.01 mm per sample and Y, Z follow a wavy section, so several axes bind along the path.
analysis::AxisProfile spiralProfile(std::size_t count) {
    std::vector<toolpath::ClRecord> records(count);
    std::vector<kinematics::MachineAxes> axes(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double phi = 0.002 * static_cast<double>(i);
        const double x = 0.01 * static_cast<double>(i);
        const double radius = 40.0 + 5.0 * std::sin(7.0 * phi);
        records[i].tip = Vec3(x, radius * std::cos(phi), radius * std::sin(phi));
        records[i].axis = Vec3(0.0, std::cos(phi), std::sin(phi));
        records[i].feed = 50.0;
        axes[i] = {x, 5.0 * std::cos(7.0 * phi), radius, phi, 0.0};
    }
    return *analysis::analyseAxisMotion(axes, records, {});
}

void BM_TimeOptimalMillionSamples(benchmark::State& state) {
    const std::size_t samples = bench::scaled<std::size_t>(1'000'000);
    const analysis::AxisProfile profile = spiralProfile(samples);
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    analysis::TimeOptimalOptions options;
    options.jerkHeuristic = state.range(0) != 0;
    double t2 = 0.0;
    for (auto _ : state) {
        auto result = analysis::timeOptimalTime(profile, machine, options);
        if (!result) {
            state.SkipWithError("T2 failed");
            break;
        }
        t2 = result->time;
        benchmark::DoNotOptimize(result);
    }
    state.counters["T2_s"] = t2;
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(samples));
}
BENCHMARK(BM_TimeOptimalMillionSamples)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

// Axis-motion analysis on a million-record program: must stay O(n) and well under 1 s.

#include "core/analysis/axis_profile.h"
#include "tests/bench/bench_size.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace {

using namespace bladeaxis;

// A spiral about X (the A axis) over a wavy section r(phi) = 40 + 5 sin(7 phi): the tip advances
// 0.01 mm per record along X while the table turns, so A = phi grows continuously as in a blade
// finishing spiral and the Y and Z slides follow the section (B is fixed, as in four-axis work).
struct HelixProgram {
    std::vector<toolpath::ClRecord> records;
    std::vector<kinematics::MachineAxes> axes;

    explicit HelixProgram(std::size_t count) {
        records.resize(count);
        axes.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const double phi = 0.002 * static_cast<double>(i);
            const double x = 0.01 * static_cast<double>(i);
            const double radius = 40.0 + 5.0 * std::sin(7.0 * phi);
            records[i].tip = Vec3(x, radius * std::cos(phi), radius * std::sin(phi));
            records[i].axis = Vec3(0.0, std::cos(phi), std::sin(phi));
            records[i].feed = 50.0;
            axes[i] = {x, 5.0 * std::cos(7.0 * phi), radius, phi, 0.0};
        }
    }
};

// A million records (a hundredth in a smoke run).
std::size_t recordCount() {
    return bench::scaled<std::size_t>(1'000'000);
}

void BM_AnalyseMillionRecords(benchmark::State& state) {
    const HelixProgram program(recordCount());
    analysis::AxisProfileOptions options;
    for (auto _ : state) {
        auto profile = analysis::analyseAxisMotion(program.axes, program.records, options);
        benchmark::DoNotOptimize(profile);
        if (!profile) {
            state.SkipWithError("analysis failed");
            break;
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recordCount()));
}
BENCHMARK(BM_AnalyseMillionRecords)->Unit(benchmark::kMillisecond);

// The million records with another derivative method than the default controller filter: the
// former default (the spline through the samples that carry motion), what the choice of default
// costs, and raw finite differences.
void analyseMillionRecordsWith(benchmark::State& state, analysis::DerivativeMethod method) {
    const HelixProgram program(recordCount());
    analysis::AxisProfileOptions options;
    options.method = method;
    for (auto _ : state) {
        auto profile = analysis::analyseAxisMotion(program.axes, program.records, options);
        benchmark::DoNotOptimize(profile);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(recordCount()));
}
BENCHMARK_CAPTURE(analyseMillionRecordsWith, Spline, analysis::DerivativeMethod::Spline)
    ->Name("BM_AnalyseMillionRecordsSpline")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(analyseMillionRecordsWith, FiniteDifference,
                  analysis::DerivativeMethod::FiniteDifference)
    ->Name("BM_AnalyseMillionRecordsFiniteDifference")
    ->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

// Parse throughput of the G-code reader on generated four-axis programs.

#include "core/base/number_io.h"
#include "core/io/nc/gcode_reader.h"
#include "core/kinematics/machine_model.h"
#include "tests/bench/bench_size.h"

#include <benchmark/benchmark.h>

#include <string>
#include <sys/resource.h>

namespace {

using bladeaxis::formatFixed;

// A four-axis blade-like program of `blocks` G1 moves, every word written.
std::string generateProgram(int blocks) {
    std::string text = "%\nO1000 (GENERATED)\nG21 G90 G94\nG0 X0.0000 Y0.0000 Z100.0000 A0.0000 "
                       "B10.0000\n";
    text.reserve(static_cast<std::size_t>(blocks) * 64 + 256);
    for (int i = 0; i < blocks; ++i) {
        const double t = static_cast<double>(i) * 1e-3;
        text += 'N';
        text += std::to_string(10 * (i + 1));
        text += " G1 X";
        text += formatFixed(-50.0 + 1e-4 * i, 4);
        text += " Y";
        text += formatFixed(40.0 * (t - static_cast<int>(t)), 4);
        text += " Z";
        text += formatFixed(30.0 + 0.001 * (i % 997), 4);
        text += " A";
        text += formatFixed(0.36 * i, 4);
        text += i == 0 ? " B10.0000 F1200.\n" : "\n";
    }
    text += "M30\n%\n";
    return text;
}

void parseOnce(benchmark::State& state, const std::string& text) {
    const auto machine = bladeaxis::kinematics::defaultBladeMachine();
    std::size_t records = 0;
    for (auto _ : state) {
        auto program = bladeaxis::io::nc::parseGcode(text, "bench.nc", machine);
        if (!program) {
            state.SkipWithError(program.error().toString().c_str());
            return;
        }
        records = program->path.records.size();
        benchmark::DoNotOptimize(program->path.records.data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(text.size()));
    state.counters["records"] = static_cast<double>(records);
    state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    state.counters["peakRssMB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void BM_ParseGcode(benchmark::State& state) {
    static const std::string text =
        generateProgram(bladeaxis::bench::scaled(400000)); // about 20 MB
    parseOnce(state, text);
}
BENCHMARK(BM_ParseGcode)->Unit(benchmark::kMillisecond);

void BM_ParseGcodeMillionBlocks(benchmark::State& state) {
    static const std::string text = generateProgram(bladeaxis::bench::scaled(1000000));
    parseOnce(state, text);
}
BENCHMARK(BM_ParseGcodeMillionBlocks)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

BENCHMARK_MAIN();

#pragma once
// The body of a benchmark executable's main, for those that must set something up first (a
// QApplication, the application's memory policy) and so cannot use BENCHMARK_MAIN.

#include <benchmark/benchmark.h>

namespace bladeaxis::bench {

inline int runBenchmarks(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

} // namespace bladeaxis::bench

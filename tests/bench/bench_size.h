#pragma once
// Input sizes of the benchmarks. `make bench` runs them at full size; the smoke tests of
// `make test` (ctest label bench) set BLADEAXIS_BENCH_SMOKE=1, and every benchmark then scales
// its input down, so that each one keeps building and running without costing test time. No
// timing is asserted anywhere.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace bladeaxis::bench {

inline bool smokeRun() {
    static const bool smoke = std::getenv("BLADEAXIS_BENCH_SMOKE") != nullptr;
    return smoke;
}

// `full` for a measurement, about a hundredth of it (at least `least`) for a smoke run.
template <class Count>
Count scaled(Count full, Count least = 1) {
    return smokeRun() ? std::max(least, static_cast<Count>(full / 100)) : full;
}

// A generated input file of one benchmark in the temporary folder; smoke runs use their own
// name, so a smoke run never leaves a small file where a measurement expects the full one.
inline std::filesystem::path benchFile(const std::string& stem, const std::string& extension) {
    return std::filesystem::temp_directory_path() /
           ("bladeaxis_bench_" + stem + (smokeRun() ? "_smoke" : "") + extension);
}

} // namespace bladeaxis::bench

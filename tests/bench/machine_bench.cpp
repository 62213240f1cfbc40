// The machine's own limits, the yardsticks of docs/performance.md: how fast fresh memory is
// first touched (page faults), copied and read. A stage that moves B bytes of fresh memory
// cannot take less than B / (first-touch rate), whatever its arithmetic.

#include "tests/bench/bench_size.h"

#include <benchmark/benchmark.h>

#include <cstring>
#include <memory>
#include <numeric>
#include <sys/mman.h>
#include <vector>

namespace {

using bladeaxis::bench::scaled;

std::size_t bufferBytes() {
    return scaled<std::size_t>(std::size_t{256} << 20, std::size_t{1} << 20);
}

// Fresh anonymous pages written once: the kernel zeroes and maps each 4 KiB page on the first
// write, as it does for every new vector of a large job.
void BM_FirstTouchFreshMemory(benchmark::State& state) {
    const std::size_t bytes = bufferBytes();
    for (auto _ : state) {
        void* memory =
            mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (memory == MAP_FAILED) {
            state.SkipWithError("mmap failed");
            break;
        }
        auto* bytesOf = static_cast<char*>(memory);
        for (std::size_t i = 0; i < bytes; i += 4096) {
            bytesOf[i] = 1;
        }
        benchmark::DoNotOptimize(bytesOf[bytes / 2]);
        munmap(memory, bytes);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_FirstTouchFreshMemory)->Unit(benchmark::kMillisecond);

// Copying between buffers already mapped: the memory bandwidth bound of a stage that only moves
// data (the writer's copy of unchanged text).
void BM_CopyMappedMemory(benchmark::State& state) {
    const std::size_t bytes = bufferBytes();
    std::vector<char> from(bytes, 'x');
    std::vector<char> to(bytes, 'y');
    for (auto _ : state) {
        std::memcpy(to.data(), from.data(), bytes);
        benchmark::DoNotOptimize(to.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_CopyMappedMemory)->Unit(benchmark::kMillisecond);

// Reading a mapped buffer once (a sum of doubles): the bound of a pass over stored arrays.
void BM_ReadMappedMemory(benchmark::State& state) {
    const std::size_t count = bufferBytes() / sizeof(double);
    std::vector<double> values(count, 1.0);
    for (auto _ : state) {
        benchmark::DoNotOptimize(std::accumulate(values.begin(), values.end(), 0.0));
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * count * sizeof(double)));
}
BENCHMARK(BM_ReadMappedMemory)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();

// Rewrite throughput of the G-code writer: the million-block program of the end-to-end
// benchmarks with every record's A and B changed, as a re-scheduled pass changes them.

#include "core/io/nc/gcode.h"
#include "core/io/program.h"
#include "core/kinematics/machine_model.h"
#include "tests/bench/million_program.h"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

using namespace bladeaxis;
namespace fs = std::filesystem;

struct RewriteInput {
    io::LoadedProgram program;
    std::vector<kinematics::MachineAxes> axes;
};

const RewriteInput& rewriteInput() {
    static const RewriteInput input = [] {
        const fs::path file = bench::writeMillionProgram(bench::benchFile("writer_million", ".nc"));
        auto program = io::loadProgram(file, kinematics::defaultBladeMachine());
        if (!program) {
            bench::fail("read", program.error());
        }
        std::vector<kinematics::MachineAxes> axes;
        axes.reserve(program->path().records.size());
        for (const toolpath::ClRecord& record : program->path().records) {
            kinematics::MachineAxes changed = *record.axes;
            changed.a += 1e-3 * std::sin(changed.a); // every A word changes
            changed.y += 1e-3;                       // and the linear axes that follow it
            changed.z -= 1e-3;
            axes.push_back(changed);
        }
        return RewriteInput{std::move(*program), std::move(axes)};
    }();
    return input;
}

void BM_RewriteMillionBlocks(benchmark::State& state) {
    const RewriteInput& input = rewriteInput();
    const auto& gcode = std::get<io::nc::GcodeProgram>(input.program.document);
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    std::size_t bytes = 0;
    for (auto _ : state) {
        auto text = io::nc::rewriteGcode(gcode, input.axes, machine);
        if (!text) {
            bench::fail("rewrite", text.error());
        }
        bytes = text->size();
        benchmark::DoNotOptimize(text->data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(bytes));
    state.counters["records"] = static_cast<double>(input.axes.size());
}
BENCHMARK(BM_RewriteMillionBlocks)->Unit(benchmark::kMillisecond)->Iterations(5);

} // namespace

BENCHMARK_MAIN();

// Blade CAD pipeline on a 200-layer program: import the blade surface from STEP, section it at
// the middle of every layer, tessellate and sample it, and check the clearance of ball, shank
// and holder at every CL point. Target: under 10 s on 2 cores (issue 6). The STEP file and the
// program are prepared outside the timed region; the counters give each stage's seconds.

#include "core/base/execution.h"
#include "core/blade/helical_path.h"
#include "core/blade/presets.h"
#include "core/cad/blade_surface.h"
#include "core/cad/cad_files.h"
#include "core/cad/clearance.h"
#include "core/cad/sections.h"
#include "core/cad/tessellation.h"
#include "tests/bench/bench_size.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <vector>

namespace {

using namespace bladeaxis;
using Clock = std::chrono::steady_clock;

const int kLayers = bench::scaled(200, 2);

struct Program {
    std::filesystem::path stepFile;
    toolpath::Toolpath path;
    std::vector<double> layerX; // mid-x of every revolution
};

// The demo profile over a 110 mm span (twist 20 -> 30 deg); 200 revolutions at 0.5 mm pitch from
// x = 5 mm. The surface has a station every 5 mm: the linear twist is reproduced within a
// micron, and the mesher's time grows with the knot count.
const Program& program() {
    static const Program p = [] {
        Program result;
        blade::BladeSpec spec = blade::demoBladeSpec();
        spec.spanEnd = 110.0;
        const blade::Blade blade = *blade::Blade::create(spec);
        result.stepFile = bench::benchFile("cad", ".step");
        (void)cad::writeCadFile(*cad::makeBladeSurface(blade, {.stationSpacing = 5.0}),
                                result.stepFile, cad::CadFormat::Step);
        blade::HelicalPathSpec pathSpec = blade::demoPathSpec();
        pathSpec.revolutions = kLayers;
        pathSpec.pitch = 0.5;
        pathSpec.xStart = 5.0;
        result.path = blade::generateHelicalPath(blade, pathSpec)->path;
        for (int k = 0; k < kLayers; ++k) {
            result.layerX.push_back(5.0 + pathSpec.pitch * (k + 0.5));
        }
        return result;
    }();
    return p;
}

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void BM_ImportSectionCheck200Layers(benchmark::State& state) {
    const Program& p = program();
    cad::ToolGeometry tool;
    tool.ballRadius = 8.0;
    const ThreadCountScope allThreads(0); // the sections and the clearance on every core
    for (auto _ : state) {
        auto start = Clock::now();
        const Result<cad::CadShape> shape = cad::readCadFile(p.stepFile);
        const double import = secondsSince(start);
        if (!shape) {
            state.SkipWithError("import failed");
            break;
        }
        start = Clock::now();
        const auto sections = cad::sectionsAtX(*shape, p.layerX);
        const double sectioning = secondsSince(start);
        start = Clock::now();
        const auto mesh = cad::tessellate(*shape, {.linearDeflection = 0.01});
        if (!sections || !mesh) {
            state.SkipWithError("sectioning or meshing failed");
            break;
        }
        const auto samples = cad::SurfaceSamples::create(*mesh, 0.25);
        const double meshing = secondsSince(start);
        if (!samples) {
            state.SkipWithError("sampling failed");
            break;
        }
        start = Clock::now();
        const auto report = cad::checkClearance(*samples, p.path, tool);
        const double clearance = secondsSince(start);
        if (!report) {
            state.SkipWithError("clearance failed");
            break;
        }
        benchmark::DoNotOptimize(report->records.data());
        state.counters["import_s"] = import;
        state.counters["section_s"] = sectioning;
        state.counters["mesh_s"] = meshing;
        state.counters["clearance_s"] = clearance;
        state.counters["records"] = static_cast<double>(p.path.records.size());
        state.counters["samples"] = static_cast<double>(samples->size());
        state.counters["sections"] = static_cast<double>(sections->size());
    }
}
BENCHMARK(BM_ImportSectionCheck200Layers)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

} // namespace

BENCHMARK_MAIN();

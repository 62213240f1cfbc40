// The 3D view's figures (issue 5): opening a program of about a million blocks and showing it in
// 3D (target: within 3 s), and the frame rate while the camera turns around the demo blade
// (target: at least 30 frames per second).
//
// VTK renders only with an X display: run under `xvfb-run -a` (run_benchmarks.sh does). The
// million-block program is the tile of tests/bench/million_tile.h repeated along x, emitted as
// G-code once in a child process (as bench_job does) so that its making is not timed.

#include "core/base/file_io.h"
#include "core/blade/helical_path.h"
#include "core/io/nc/gcode.h"
#include "core/io/program.h"
#include "core/job/display_scene.h"
#include "core/job/job.h"
#include "tests/bench/bench_main.h"
#include "tests/bench/million_program.h"
#include "ui/toolpath_view.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QMouseEvent>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace {

using namespace bladeaxis;
namespace fs = std::filesystem;
using bench::fail;
using Clock = std::chrono::steady_clock;

constexpr double kToolRadius = 8.0; // mm, the demo path's ball
constexpr int kFrameWidth = 800, kFrameHeight = 600;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

const fs::path& millionProgram() {
    static const fs::path file =
        bench::writeMillionProgram(bench::benchFile("view_million", ".nc"));
    return file;
}

// The cutting pass as the job finds it: the longest run of feed records.
std::span<const toolpath::ClRecord> longestFeedRun(const std::vector<toolpath::ClRecord>& records) {
    std::size_t bestFirst = 0, bestCount = 0, first = 0;
    for (std::size_t i = 0; i <= records.size(); ++i) {
        if (i < records.size() && records[i].motion == toolpath::MotionKind::Feed) {
            continue;
        }
        if (i - first > bestCount) {
            bestFirst = first;
            bestCount = i - first;
        }
        first = i + 1;
    }
    return std::span(records).subspan(bestFirst, bestCount);
}

// Read the program, build its display scene (the original toolpath: no schedule, no CAD, so
// the blade is reconstructed from the contact points) and render the first frame.
void BM_OpenMillionBlockProgramIn3D(benchmark::State& state) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    millionProgram();
    double readSeconds = 0.0, sceneSeconds = 0.0, showSeconds = 0.0, renderSeconds = 0.0;
    double nextFrameSeconds = 0.0;
    job::DisplayScene scene;
    for (auto _ : state) {
        const auto start = Clock::now();
        auto program = io::loadProgram(millionProgram(), machine);
        if (!program) {
            fail("read", program.error());
        }
        readSeconds = secondsSince(start);
        const auto sceneStart = Clock::now();
        job::DisplaySceneInput input;
        input.pass = longestFeedRun(program->path().records);
        input.toolRadius = kToolRadius;
        scene = job::buildDisplayScene(input);
        sceneSeconds = secondsSince(sceneStart);
        const auto showStart = Clock::now();
        ui::ToolpathView view;
        view.resize(kFrameWidth, kFrameHeight);
        view.showScene(scene);
        showSeconds = secondsSince(showStart);
        const auto renderStart = Clock::now();
        benchmark::DoNotOptimize(view.renderFrame());
        renderSeconds = secondsSince(renderStart);
        state.PauseTiming();
        const auto nextStart = Clock::now();
        benchmark::DoNotOptimize(view.renderFrame());
        nextFrameSeconds = secondsSince(nextStart);
        state.ResumeTiming();
    }
    state.counters["records"] = static_cast<double>(scene.passRecords);
    state.counters["drawn_points"] = static_cast<double>(scene.tips.size());
    state.counters["triangles"] = static_cast<double>(scene.surface.triangles.size());
    state.counters["read_s"] = readSeconds;
    state.counters["scene_s"] = sceneSeconds;
    state.counters["show_s"] = showSeconds;
    state.counters["first_frame_s"] = renderSeconds;
    state.counters["next_frame_s"] = nextFrameSeconds; // not timed: the steady frame of this scene
}
BENCHMARK(BM_OpenMillionBlockProgramIn3D)->Unit(benchmark::kMillisecond)->Iterations(2);

const job::DisplayScene& demoScene() {
    static const job::DisplayScene scene = [] {
        job::JobSpec spec;
        spec.demo = true;
        NullProgressSink progress;
        CancelToken cancel;
        auto result = job::runJob(spec, progress, cancel);
        if (!result) {
            fail("demo job", result.error());
        }
        return job::buildDisplayScene(*result);
    }();
    return scene;
}

void sendMouse(ui::ToolpathView& view, QEvent::Type type, QPointF position) {
    QMouseEvent event(type, position, view.mapToGlobal(position), Qt::LeftButton,
                      type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton,
                      Qt::NoModifier);
    QApplication::sendEvent(&view, &event);
}

// One frame per iteration while a left drag turns the camera (VTK's trackball style), read back
// into the QImage the widget paints; the blade surface, toolpath and both glyph sets shown.
// Argument 0: with the tool-axis glyphs; 1: without them (blade and toolpath only).
void BM_RotateDemoBlade(benchmark::State& state) {
    ui::ToolpathView view;
    view.resize(kFrameWidth, kFrameHeight);
    view.showScene(demoScene());
    view.setOriginalAxesVisible(state.range(0) == 0);
    view.setRescheduledAxesVisible(state.range(0) == 0);
    view.renderFrame(); // the context and the buffers are made on the first frame
    QPointF position(kFrameWidth / 2.0, kFrameHeight / 2.0);
    sendMouse(view, QEvent::MouseButtonPress, position);
    double step = 4.0;
    for (auto _ : state) {
        position.rx() += step;
        if (position.x() > kFrameWidth - 50.0 || position.x() < 50.0) {
            step = -step;
        }
        sendMouse(view, QEvent::MouseMove, position);
        benchmark::DoNotOptimize(view.renderFrame());
    }
    sendMouse(view, QEvent::MouseButtonRelease, position);
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["triangles"] = static_cast<double>(demoScene().surface.triangles.size());
    state.counters["drawn_points"] = static_cast<double>(demoScene().tips.size());
}
BENCHMARK(BM_RotateDemoBlade)
    ->ArgName("without_glyphs")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();

} // namespace

int main(int argc, char** argv) {
    QApplication application(argc, argv);
    return bladeaxis::bench::runBenchmarks(argc, argv);
}

// One step of a key-point drag in the S-theta editor, as the engineer sees it: the mouse move
// re-smooths the 5,000-sample layer (core's resmoothLayer) and the editor repaints (target:
// under 16 ms, one frame at 60 Hz). The job's re-run with the edit happens after the release,
// in the background, and is not part of the frame.
//
// QPainter draws into an image, so no display is needed (the offscreen platform is used when
// none is set).

#include "tests/bench/s_shaped_layer.h"
#include "ui/s_theta_editor.h"

#include <benchmark/benchmark.h>

#include <QApplication>
#include <QImage>
#include <QMouseEvent>

namespace {

using bladeaxis::bench::sShapedLayer;

void sendMouse(QWidget& widget, QEvent::Type type, QPointF at) {
    const Qt::MouseButtons buttons =
        type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent event(type, at, widget.mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
    QApplication::sendEvent(&widget, &event);
}

void dragStepWithRepaint(benchmark::State& state) {
    bladeaxis::ui::SThetaEditor editor;
    editor.resize(900, 600);
    editor.setLayer(sShapedLayer(), bladeaxis::scheduling::bestPreset(), 0);
    QImage frame(editor.size(), QImage::Format_ARGB32_Premultiplied);
    const QPointF start = editor.vertexPosition(2);
    sendMouse(editor, QEvent::MouseButtonPress, start);
    double dy = 4.0;
    for (auto _ : state) {
        sendMouse(editor, QEvent::MouseMove, start + QPointF(0.0, dy));
        dy = -dy;
        editor.render(&frame);
        if (!editor.refusal().isEmpty()) {
            state.SkipWithError(editor.refusal().toStdString().c_str());
            break;
        }
    }
    sendMouse(editor, QEvent::MouseButtonRelease, start);
    state.SetLabel("5000-sample layer: re-smooth + repaint 900x600");
}
BENCHMARK(dragStepWithRepaint)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication application(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

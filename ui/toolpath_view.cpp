#include "ui/toolpath_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace bladeaxis::ui {

struct ToolpathView::Scene {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkPolyData> path;
    vtkNew<vtkPolyDataMapper> pathMapper;
    vtkNew<vtkActor> pathActor;
    vtkNew<vtkPolyData> glyphs;
    vtkNew<vtkPolyDataMapper> glyphMapper;
    vtkNew<vtkActor> glyphActor;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    vtkNew<vtkSphereSource> ball;
    vtkNew<vtkPolyDataMapper> ballMapper;
    vtkNew<vtkActor> ballActor;
    vtkNew<vtkLineSource> shank;
    vtkNew<vtkPolyDataMapper> shankMapper;
    vtkNew<vtkActor> shankActor;
    std::vector<Vec3> tips, axes;
    double toolRadius = 4.0;
    std::vector<std::pair<std::size_t, std::size_t>> layerRanges;
    int selected = -1;
    bool hasData = false;
};

namespace {

QColor layerColour(std::size_t layer, int selected) {
    if (static_cast<int>(layer) == selected) {
        return QColor(255, 60, 40);
    }
    return QColor::fromHsv(static_cast<int>((layer * 47) % 300), 160, 220);
}

} // namespace

ToolpathView::ToolpathView(QWidget* parent) : QWidget(parent), m_scene(std::make_unique<Scene>()) {
    setMinimumSize(320, 240);
    setToolTip(tr("Toolpath coloured by layer (selected layer in red), re-scheduled tool axes"));
    m_scene->window->SetOffScreenRendering(1);
    m_scene->window->AddRenderer(m_scene->renderer);
    m_scene->renderer->SetBackground(0.12, 0.12, 0.14);
    m_scene->pathMapper->SetInputData(m_scene->path);
    m_scene->pathActor->SetMapper(m_scene->pathMapper);
    m_scene->pathActor->GetProperty()->SetLineWidth(2.0);
    m_scene->glyphMapper->SetInputData(m_scene->glyphs);
    m_scene->glyphActor->SetMapper(m_scene->glyphMapper);
    m_scene->glyphActor->GetProperty()->SetColor(0.85, 0.85, 0.85);
    m_scene->renderer->AddActor(m_scene->pathActor);
    m_scene->renderer->AddActor(m_scene->glyphActor);
    m_scene->ball->SetThetaResolution(24);
    m_scene->ball->SetPhiResolution(16);
    m_scene->ballMapper->SetInputConnection(m_scene->ball->GetOutputPort());
    m_scene->ballActor->SetMapper(m_scene->ballMapper);
    m_scene->ballActor->GetProperty()->SetColor(0.9, 0.75, 0.3);
    m_scene->shankMapper->SetInputConnection(m_scene->shank->GetOutputPort());
    m_scene->shankActor->SetMapper(m_scene->shankMapper);
    m_scene->shankActor->GetProperty()->SetColor(0.9, 0.75, 0.3);
    m_scene->shankActor->GetProperty()->SetLineWidth(6.0);
    m_scene->ballActor->VisibilityOff();
    m_scene->shankActor->VisibilityOff();
    m_scene->renderer->AddActor(m_scene->ballActor);
    m_scene->renderer->AddActor(m_scene->shankActor);
    m_scene->interactor->SetRenderWindow(m_scene->window);
    m_scene->interactor->SetInteractorStyle(m_scene->style);
    // The widget repaints on every event; VTK must not try to render into a window of its own.
    m_scene->interactor->EnableRenderOff();
}

ToolpathView::~ToolpathView() = default;

void ToolpathView::setSchedule(const scheduling::ScheduleResult& schedule) {
    Scene& scene = *m_scene;
    vtkNew<vtkPoints> points;
    for (const Vec3& tip : schedule.newTips) {
        points->InsertNextPoint(tip.x(), tip.y(), tip.z());
    }
    vtkNew<vtkCellArray> lines;
    scene.layerRanges.clear();
    for (const scheduling::LayerResult& layer : schedule.layers) {
        const std::size_t last = std::min(layer.last, schedule.newTips.size() - 1);
        scene.layerRanges.emplace_back(layer.first, last);
        lines->InsertNextCell(static_cast<int>(last - layer.first + 1));
        for (std::size_t i = layer.first; i <= last; ++i) {
            lines->InsertCellPoint(static_cast<vtkIdType>(i));
        }
    }
    scene.path->SetPoints(points);
    scene.path->SetLines(lines);

    // Every 20th tool axis as a 10 mm line from the tip.
    constexpr std::size_t kStride = 20;
    constexpr double kGlyphMm = 10.0;
    vtkNew<vtkPoints> glyphPoints;
    vtkNew<vtkCellArray> glyphLines;
    for (std::size_t i = 0; i < schedule.newAxes.size() && i < schedule.newTips.size();
         i += kStride) {
        const Vec3 tip = schedule.newTips[i];
        const Vec3 end = tip + kGlyphMm * schedule.newAxes[i];
        const vtkIdType a = glyphPoints->InsertNextPoint(tip.x(), tip.y(), tip.z());
        const vtkIdType b = glyphPoints->InsertNextPoint(end.x(), end.y(), end.z());
        const vtkIdType ids[2] = {a, b};
        glyphLines->InsertNextCell(2, ids);
    }
    scene.glyphs->SetPoints(glyphPoints);
    scene.glyphs->SetLines(glyphLines);
    scene.tips = schedule.newTips;
    scene.axes = schedule.newAxes;
    scene.hasData = !schedule.newTips.empty();
    setSelectedLayer(scene.selected);
    scene.renderer->ResetCamera();
    scene.renderer->GetActiveCamera()->Elevation(25.0);
    scene.renderer->ResetCameraClippingRange();
    update();
}

void ToolpathView::setSelectedLayer(int layer) {
    Scene& scene = *m_scene;
    scene.selected = layer;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    for (std::size_t i = 0; i < scene.layerRanges.size(); ++i) {
        const QColor colour = layerColour(i, layer);
        const unsigned char rgb[3] = {static_cast<unsigned char>(colour.red()),
                                      static_cast<unsigned char>(colour.green()),
                                      static_cast<unsigned char>(colour.blue())};
        colours->InsertNextTypedTuple(rgb);
    }
    scene.path->GetCellData()->SetScalars(colours);
    scene.path->Modified();
    update();
}

void ToolpathView::setToolRadius(double radius) {
    m_scene->toolRadius = radius > 0.0 ? radius : 4.0;
}

void ToolpathView::showToolAt(std::size_t sample) {
    Scene& scene = *m_scene;
    if (sample >= scene.tips.size() || sample >= scene.axes.size()) {
        scene.ballActor->VisibilityOff();
        scene.shankActor->VisibilityOff();
        update();
        return;
    }
    // The tip is the lowest point of the ball; its centre sits one radius up the tool axis.
    constexpr double kShankLengthMm = 40.0;
    const Vec3 centre = scene.tips[sample] + scene.toolRadius * scene.axes[sample];
    const Vec3 top = centre + kShankLengthMm * scene.axes[sample];
    scene.ball->SetCenter(centre.x(), centre.y(), centre.z());
    scene.ball->SetRadius(scene.toolRadius);
    scene.shank->SetPoint1(centre.x(), centre.y(), centre.z());
    scene.shank->SetPoint2(top.x(), top.y(), top.z());
    scene.ballActor->VisibilityOn();
    scene.shankActor->VisibilityOn();
    scene.renderer->ResetCameraClippingRange();
    update();
}

QImage ToolpathView::renderFrame() {
    const int w = std::max(width(), 16);
    const int h = std::max(height(), 16);
    m_scene->window->SetSize(w, h);
    m_scene->window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    m_scene->window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels);
    // VTK's rows start at the bottom.
    QImage image(reinterpret_cast<const uchar*>(pixels->GetPointer(0)), w, h, 4 * w,
                 QImage::Format_RGBX8888);
    return image.mirrored();
}

void ToolpathView::forward(QMouseEvent* event, unsigned long vtkEvent) {
    const QPointF position = event->position();
    m_scene->window->SetSize(std::max(width(), 16), std::max(height(), 16));
    m_scene->interactor->SetSize(std::max(width(), 16), std::max(height(), 16));
    m_scene->interactor->SetEventInformationFlipY(
        static_cast<int>(position.x()), static_cast<int>(position.y()),
        (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
        (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
    m_scene->interactor->InvokeEvent(vtkEvent, nullptr);
    update();
}

void ToolpathView::mousePressEvent(QMouseEvent* event) {
    switch (event->button()) {
    case Qt::LeftButton:
        forward(event, vtkCommand::LeftButtonPressEvent);
        break;
    case Qt::RightButton:
        forward(event, vtkCommand::RightButtonPressEvent);
        break;
    case Qt::MiddleButton:
        forward(event, vtkCommand::MiddleButtonPressEvent);
        break;
    default:
        break;
    }
}

void ToolpathView::mouseReleaseEvent(QMouseEvent* event) {
    switch (event->button()) {
    case Qt::LeftButton:
        forward(event, vtkCommand::LeftButtonReleaseEvent);
        break;
    case Qt::RightButton:
        forward(event, vtkCommand::RightButtonReleaseEvent);
        break;
    case Qt::MiddleButton:
        forward(event, vtkCommand::MiddleButtonReleaseEvent);
        break;
    default:
        break;
    }
}

void ToolpathView::mouseMoveEvent(QMouseEvent* event) {
    forward(event, vtkCommand::MouseMoveEvent);
}

void ToolpathView::wheelEvent(QWheelEvent* event) {
    m_scene->interactor->InvokeEvent(event->angleDelta().y() > 0
                                         ? vtkCommand::MouseWheelForwardEvent
                                         : vtkCommand::MouseWheelBackwardEvent,
                                     nullptr);
    update();
}

void ToolpathView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (!m_scene->hasData) {
        painter.fillRect(rect(), palette().base());
        painter.drawText(rect(), Qt::AlignCenter, tr("Run a job to see the toolpath"));
        return;
    }
    painter.drawImage(0, 0, renderFrame());
}

} // namespace bladeaxis::ui

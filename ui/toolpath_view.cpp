#include "ui/toolpath_view.h"

#include <QLinearGradient>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLineSource.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace bladeaxis::ui {

// A drawn item: its data, mapper and actor.
struct Drawn {
    vtkNew<vtkPolyData> data;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;

    Drawn() {
        mapper->SetInputData(data);
        actor->SetMapper(mapper);
    }
};

struct ToolpathView::Scene {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    Drawn surface, path, originalGlyphs, rescheduledGlyphs, section;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    vtkNew<vtkSphereSource> ball;
    vtkNew<vtkPolyDataMapper> ballMapper;
    vtkNew<vtkActor> ballActor;
    vtkNew<vtkLineSource> shank;
    vtkNew<vtkPolyDataMapper> shankMapper;
    vtkNew<vtkActor> shankActor;
    job::DisplayScene scene;
    double toolRadius = 4.0;
    double speedScale = 0.0; // rad/s at the top of the colour bar
    bool hasData = false;
};

namespace {

constexpr unsigned char kSelectedRgb[3] = {255, 60, 40};

QColor layerColour(std::size_t layer) {
    return QColor::fromHsv(static_cast<int>((layer * 47) % 300), 160, 220);
}

// Blue (slow) through green and yellow to red (fast).
QColor speedColour(double fraction) {
    const double clamped = std::clamp(fraction, 0.0, 1.0);
    return QColor::fromHsvF(static_cast<float>((1.0 - clamped) * 240.0 / 360.0), 0.85F, 0.95F);
}

void appendRgb(vtkUnsignedCharArray* colours, const QColor& colour) {
    const unsigned char rgb[3] = {static_cast<unsigned char>(colour.red()),
                                  static_cast<unsigned char>(colour.green()),
                                  static_cast<unsigned char>(colour.blue())};
    colours->InsertNextTypedTuple(rgb);
}

vtkNew<vtkPoints> pointsOf(const std::vector<Vec3>& positions) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t i = 0; i < positions.size(); ++i) {
        points->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
    }
    return points;
}

void fillSurface(vtkPolyData* data, const job::DisplayScene& scene) {
    vtkNew<vtkCellArray> triangles;
    for (const auto& t : scene.surface.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        triangles->InsertNextCell(3, ids);
    }
    vtkNew<vtkDoubleArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(scene.surfaceNormals.size()));
    for (std::size_t i = 0; i < scene.surfaceNormals.size(); ++i) {
        normals->SetTypedTuple(static_cast<vtkIdType>(i), scene.surfaceNormals[i].data());
    }
    data->SetPoints(pointsOf(scene.surface.vertices));
    data->SetPolys(triangles);
    if (scene.surfaceNormals.size() == scene.surface.vertices.size()) {
        data->GetPointData()->SetNormals(normals);
    }
    data->Modified();
}

// One polyline per layer, joined to the first point of the next layer so the path is unbroken.
void fillPath(vtkPolyData* data, const job::DisplayScene& scene) {
    vtkNew<vtkCellArray> lines;
    for (std::size_t k = 0; k < scene.layers.size(); ++k) {
        const job::DisplayLayer& layer = scene.layers[k];
        const std::size_t end = k + 1 < scene.layers.size() ? layer.lastPoint + 1 : layer.lastPoint;
        lines->InsertNextCell(static_cast<int>(end - layer.firstPoint + 1));
        for (std::size_t i = layer.firstPoint; i <= end; ++i) {
            lines->InsertCellPoint(static_cast<vtkIdType>(i));
        }
    }
    data->SetPoints(pointsOf(scene.tips));
    data->SetLines(lines);
    data->Modified();
}

// Tool axes as lines from the ball centre: both orientations turn about the same centre, so
// the two sets show the re-scheduled rotation directly.
void fillGlyphs(vtkPolyData* data, const job::DisplayScene& scene, const std::vector<Vec3>& axes,
                double length) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    if (axes.size() == scene.centres.size()) {
        for (const std::size_t i : scene.glyphPoints) {
            const Vec3 start = scene.centres[i];
            const Vec3 end = start + length * axes[i];
            const vtkIdType ids[2] = {points->InsertNextPoint(start.data()),
                                      points->InsertNextPoint(end.data())};
            lines->InsertNextCell(2, ids);
        }
    }
    data->SetPoints(points);
    data->SetLines(lines);
    data->Modified();
}

// Top of the colour bar: the 98th percentile of either program's speeds, so that the
// original's reversal spikes do not turn the whole re-scheduled path blue (faster is red).
double speedScaleOf(const job::DisplayScene& scene) {
    double scale = 0.0;
    for (const auto* speeds : {&scene.aSpeedOriginal, &scene.aSpeedRescheduled}) {
        if (speeds->empty()) {
            continue;
        }
        std::vector<double> sorted = *speeds;
        const auto rank =
            static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(sorted.size() - 1));
        std::nth_element(sorted.begin(), sorted.begin() + rank, sorted.end());
        scale = std::max(scale, sorted[static_cast<std::size_t>(rank)]);
    }
    return scale;
}

} // namespace

ToolpathView::ToolpathView(QWidget* parent) : QWidget(parent), m_vtk(std::make_unique<Scene>()) {
    setMinimumSize(320, 240);
    setToolTip(tr("Blade and toolpath: left drag rotates, right drag or wheel zooms, middle "
                  "drag pans. Tool axes from the ball centre: original orange, re-scheduled "
                  "cyan; the selected layer's blade section in yellow"));
    Scene& vtk = *m_vtk;
    vtk.window->SetOffScreenRendering(1);
    // VTK asks for 8x multisampling by default; on Mesa's software renderer (Xvfb, remote
    // desktops) that costs ~35 ms of an 800x600 frame against ~5 ms without (bench_view).
    vtk.window->SetMultiSamples(0);
    vtk.window->AddRenderer(vtk.renderer);
    vtk.renderer->SetBackground(0.12, 0.12, 0.14);

    vtk.surface.actor->GetProperty()->SetColor(0.62, 0.66, 0.72);
    vtk.surface.actor->GetProperty()->SetSpecular(0.2);
    // The tips lie on the ball, just off the surface: push the surface back in depth.
    vtk.surface.mapper->SetResolveCoincidentTopologyToPolygonOffset();
    vtk.surface.mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 4.0);
    vtk.section.mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -4.0);
    vtk.surface.mapper->ScalarVisibilityOff();
    vtk.path.actor->GetProperty()->SetLineWidth(2.0);
    vtk.path.actor->GetProperty()->LightingOff();
    vtk.path.mapper->SetColorModeToDirectScalars();
    vtk.originalGlyphs.actor->GetProperty()->SetColor(1.0, 0.6, 0.2);
    vtk.rescheduledGlyphs.actor->GetProperty()->SetColor(0.3, 0.9, 1.0);
    vtk.section.actor->GetProperty()->SetColor(1.0, 0.92, 0.2);
    vtk.section.actor->GetProperty()->SetLineWidth(4.0);
    for (Drawn* drawn : {&vtk.originalGlyphs, &vtk.rescheduledGlyphs, &vtk.section}) {
        drawn->actor->GetProperty()->LightingOff();
        drawn->mapper->ScalarVisibilityOff();
    }
    for (Drawn* drawn :
         {&vtk.surface, &vtk.path, &vtk.originalGlyphs, &vtk.rescheduledGlyphs, &vtk.section}) {
        vtk.renderer->AddActor(drawn->actor);
    }

    vtk.ball->SetThetaResolution(24);
    vtk.ball->SetPhiResolution(16);
    vtk.ballMapper->SetInputConnection(vtk.ball->GetOutputPort());
    vtk.ballActor->SetMapper(vtk.ballMapper);
    vtk.ballActor->GetProperty()->SetColor(0.9, 0.75, 0.3);
    vtk.shankMapper->SetInputConnection(vtk.shank->GetOutputPort());
    vtk.shankActor->SetMapper(vtk.shankMapper);
    vtk.shankActor->GetProperty()->SetColor(0.9, 0.75, 0.3);
    vtk.shankActor->GetProperty()->SetLineWidth(6.0);
    vtk.ballActor->VisibilityOff();
    vtk.shankActor->VisibilityOff();
    vtk.renderer->AddActor(vtk.ballActor);
    vtk.renderer->AddActor(vtk.shankActor);
    vtk.interactor->SetRenderWindow(vtk.window);
    vtk.interactor->SetInteractorStyle(vtk.style);
    // The widget repaints on every event; VTK must not try to render into a window of its own.
    vtk.interactor->EnableRenderOff();
}

ToolpathView::~ToolpathView() = default;

void ToolpathView::showScene(const job::DisplayScene& scene) {
    Scene& vtk = *m_vtk;
    const bool first = !vtk.hasData;
    vtk.scene = scene;
    if (scene.toolRadius > 0.0) {
        vtk.toolRadius = scene.toolRadius;
    }
    vtk.speedScale = speedScaleOf(scene);
    fillSurface(vtk.surface.data, scene);
    fillPath(vtk.path.data, scene);
    const double glyphLength = scene.toolRadius > 0.0 ? 1.5 * scene.toolRadius : 10.0;
    fillGlyphs(vtk.originalGlyphs.data, scene, scene.originalAxes, glyphLength);
    fillGlyphs(vtk.rescheduledGlyphs.data, scene, scene.rescheduledAxes, glyphLength);
    vtk.hasData = !scene.empty();
    vtk.ballActor->VisibilityOff();
    vtk.shankActor->VisibilityOff();
    if (m_selected >= static_cast<int>(scene.layers.size())) {
        m_selected = -1;
    }
    updatePathColours();
    updateSection();
    if (first) {
        resetView();
    } else {
        vtk.renderer->ResetCameraClippingRange();
    }
    update();
}

const job::DisplayScene& ToolpathView::scene() const {
    return m_vtk->scene;
}

void ToolpathView::setSchedule(const scheduling::ScheduleResult& schedule) {
    std::vector<toolpath::ClRecord> records(schedule.newTips.size());
    for (std::size_t i = 0; i < records.size() && i < schedule.newAxes.size(); ++i) {
        records[i].tip = schedule.newTips[i];
        records[i].axis = schedule.newAxes[i];
    }
    job::DisplaySceneInput input;
    input.pass = records;
    input.toolRadius = m_vtk->toolRadius;
    input.schedule = &schedule;
    showScene(job::buildDisplayScene(input));
}

void ToolpathView::setSelectedLayer(int layer) {
    m_selected = layer;
    updatePathColours();
    updateSection();
    update();
}

void ToolpathView::setColouring(Colouring colouring) {
    m_colouring = colouring;
    updatePathColours();
    update();
}

void ToolpathView::setOriginalAxesVisible(bool visible) {
    m_vtk->originalGlyphs.actor->SetVisibility(visible);
    update();
}

void ToolpathView::setRescheduledAxesVisible(bool visible) {
    m_vtk->rescheduledGlyphs.actor->SetVisibility(visible);
    update();
}

void ToolpathView::setSurfaceVisible(bool visible) {
    m_vtk->surface.actor->SetVisibility(visible);
    update();
}

void ToolpathView::updatePathColours() {
    Scene& vtk = *m_vtk;
    const job::DisplayScene& scene = vtk.scene;
    const std::vector<double>* speeds = nullptr;
    if (m_colouring == Colouring::ASpeed) {
        speeds = scene.aSpeedRescheduled.empty() ? &scene.aSpeedOriginal : &scene.aSpeedRescheduled;
    } else if (m_colouring == Colouring::OriginalASpeed) {
        speeds = &scene.aSpeedOriginal;
    }
    if (speeds != nullptr && speeds->size() != scene.tips.size()) {
        speeds = nullptr; // not analysed: fall back to the layers
    }
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->Allocate(static_cast<vtkIdType>(3 * scene.tips.size()));
    const double scale = vtk.speedScale > 0.0 ? vtk.speedScale : 1.0;
    for (std::size_t i = 0; i < scene.tips.size(); ++i) {
        if (speeds != nullptr) {
            appendRgb(colours, speedColour((*speeds)[i] / scale));
        } else if (static_cast<int>(scene.layer[i]) == m_selected) {
            colours->InsertNextTypedTuple(kSelectedRgb);
        } else {
            appendRgb(colours, layerColour(scene.layer[i]));
        }
    }
    vtk.path.data->GetPointData()->SetScalars(colours);
    vtk.path.data->Modified();
}

void ToolpathView::updateSection() {
    Scene& vtk = *m_vtk;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    if (m_selected >= 0 && static_cast<std::size_t>(m_selected) < vtk.scene.layers.size()) {
        for (const cad::Polyline3& piece :
             vtk.scene.layers[static_cast<std::size_t>(m_selected)].section) {
            if (piece.points.size() < 2) {
                continue;
            }
            const vtkIdType first = points->GetNumberOfPoints();
            for (const Vec3& p : piece.points) {
                points->InsertNextPoint(p.data());
            }
            const auto count = static_cast<vtkIdType>(piece.points.size());
            lines->InsertNextCell(static_cast<int>(count + (piece.closed ? 1 : 0)));
            for (vtkIdType i = 0; i < count; ++i) {
                lines->InsertCellPoint(first + i);
            }
            if (piece.closed) {
                lines->InsertCellPoint(first);
            }
        }
    }
    vtk.section.data->SetPoints(points);
    vtk.section.data->SetLines(lines);
    vtk.section.data->Modified();
}

void ToolpathView::setToolRadius(double radius) {
    m_vtk->toolRadius = radius > 0.0 ? radius : 4.0;
}

void ToolpathView::showToolAt(std::size_t record) {
    Scene& vtk = *m_vtk;
    const job::DisplayScene& scene = vtk.scene;
    if (scene.empty() || record > scene.record.back()) {
        vtk.ballActor->VisibilityOff();
        vtk.shankActor->VisibilityOff();
        update();
        return;
    }
    const auto drawn = static_cast<std::size_t>(
        std::lower_bound(scene.record.begin(), scene.record.end(), record) - scene.record.begin());
    const Vec3 axis =
        scene.hasRescheduled() ? scene.rescheduledAxes[drawn] : scene.originalAxes[drawn];
    // The tip is the lowest point of the ball; its centre sits one radius up the tool axis.
    constexpr double kShankLengthMm = 40.0;
    const Vec3 centre = scene.tips[drawn] + vtk.toolRadius * axis;
    const Vec3 top = centre + kShankLengthMm * axis;
    vtk.ball->SetCenter(centre.x(), centre.y(), centre.z());
    vtk.ball->SetRadius(vtk.toolRadius);
    vtk.shank->SetPoint1(centre.x(), centre.y(), centre.z());
    vtk.shank->SetPoint2(top.x(), top.y(), top.z());
    vtk.ballActor->VisibilityOn();
    vtk.shankActor->VisibilityOn();
    vtk.renderer->ResetCameraClippingRange();
    update();
}

void ToolpathView::lookFrom(const double direction[3], const double viewUp[3]) {
    vtkCamera* camera = m_vtk->renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(direction[0], direction[1], direction[2]);
    camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
    fitView();
}

void ToolpathView::viewFront() {
    const double direction[3] = {0.0, -1.0, 0.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::viewTop() {
    const double direction[3] = {0.0, 0.0, 1.0}, up[3] = {0.0, 1.0, 0.0};
    lookFrom(direction, up);
}

void ToolpathView::viewSide() {
    const double direction[3] = {1.0, 0.0, 0.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::viewIsometric() {
    const double direction[3] = {1.0, -1.0, 1.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::fitView() {
    m_vtk->renderer->ResetCamera();
    m_vtk->renderer->ResetCameraClippingRange();
    update();
}

void ToolpathView::resetView() {
    viewIsometric();
}

QImage ToolpathView::renderFrame() {
    const int w = std::max(width(), 16);
    const int h = std::max(height(), 16);
    m_vtk->window->SetSize(w, h);
    m_vtk->window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    m_vtk->window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels);
    // VTK's rows start at the bottom.
    QImage frame = QImage(reinterpret_cast<const uchar*>(pixels->GetPointer(0)), w, h, 4 * w,
                          QImage::Format_RGBX8888)
                       .mirrored();
    if (m_vtk->hasData) {
        paintOverlay(frame);
    }
    return frame;
}

// The colour legend (top left) and the W axes as the camera sees them (bottom left), painted
// by Qt on the frame: cheaper than VTK's annotation actors and identical in screenshots.
void ToolpathView::paintOverlay(QImage& frame) {
    QPainter painter(&frame);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QColor(230, 230, 230));
    const job::DisplayScene& scene = m_vtk->scene;
    const bool bySpeed = m_colouring != Colouring::Layer && !scene.aSpeedOriginal.empty();
    if (bySpeed) {
        const QRect bar(12, 28, 160, 12);
        QLinearGradient gradient(bar.topLeft(), bar.topRight());
        for (int step = 0; step <= 8; ++step) {
            gradient.setColorAt(step / 8.0, speedColour(step / 8.0));
        }
        painter.fillRect(bar, gradient);
        const bool original =
            m_colouring == Colouring::OriginalASpeed || scene.aSpeedRescheduled.empty();
        painter.drawText(
            12, 20, original ? tr("|dA/dt| original (rad/s)") : tr("|dA/dt| re-scheduled (rad/s)"));
        painter.drawText(12, 56, QStringLiteral("0"));
        painter.drawText(bar.right() - 40, 56,
                         QStringLiteral("\u2265 ") + QString::number(m_vtk->speedScale, 'g', 3));
    } else {
        painter.drawText(12, 20,
                         m_selected >= 0 ? tr("Coloured by layer; layer %1 in red").arg(m_selected)
                                         : tr("Coloured by layer"));
    }
    painter.drawText(12, bySpeed ? 74 : 38,
                     tr("Blade: %1").arg(QString::fromStdString(scene.surfaceName)));

    // Rows of the view matrix are the camera's right, up and backward directions in W.
    vtkMatrix4x4* view = m_vtk->renderer->GetActiveCamera()->GetViewTransformMatrix();
    const QPointF origin(40.0, frame.height() - 40.0);
    const char* names[3] = {"X", "Y", "Z"};
    const QColor colours[3] = {QColor(230, 80, 70), QColor(90, 200, 90), QColor(90, 140, 240)};
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF tip =
            origin + 26.0 * QPointF(view->GetElement(0, axis), -view->GetElement(1, axis));
        painter.setPen(QPen(colours[axis], 2.0));
        painter.drawLine(origin, tip);
        painter.drawText(tip + QPointF(3.0, 4.0), QString::fromLatin1(names[axis]));
    }
}

void ToolpathView::forward(QMouseEvent* event, unsigned long vtkEvent) {
    const QPointF position = event->position();
    m_vtk->window->SetSize(std::max(width(), 16), std::max(height(), 16));
    m_vtk->interactor->SetSize(std::max(width(), 16), std::max(height(), 16));
    m_vtk->interactor->SetEventInformationFlipY(static_cast<int>(position.x()),
                                                static_cast<int>(position.y()),
                                                (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                                (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
    m_vtk->interactor->InvokeEvent(vtkEvent, nullptr);
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
    m_vtk->interactor->InvokeEvent(event->angleDelta().y() > 0
                                       ? vtkCommand::MouseWheelForwardEvent
                                       : vtkCommand::MouseWheelBackwardEvent,
                                   nullptr);
    update();
}

void ToolpathView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (!m_vtk->hasData) {
        painter.fillRect(rect(), palette().base());
        painter.drawText(rect(), Qt::AlignCenter,
                         tr("Run a job to see the blade and the toolpath"));
        return;
    }
    painter.drawImage(0, 0, renderFrame());
}

} // namespace bladeaxis::ui

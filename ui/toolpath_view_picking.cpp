// The mouse in the 3D view: drags turn, zoom and pan the camera (VTK's trackball style); a click
// without a drag picks the toolpath point under it.
#include "ui/toolpath_view.h"
#include "ui/toolpath_view_scene.h"

#include <QMouseEvent>
#include <QWheelEvent>
#include <cmath>
#include <limits>
#include <optional>
#include <vtkCommand.h>

namespace bladeaxis::ui {

using namespace detail;

namespace {

// A press and release closer than this (widget pixels) is a click, not a drag.
constexpr double kClickSlopPx = 3.0;
// A picked point of the blade surface selects the path point drawn within this distance.
constexpr double kPickRadiusPx = 10.0;

// VTK's press or release event of a mouse button; none for the other buttons.
std::optional<unsigned long> vtkButtonEvent(Qt::MouseButton button, bool press) {
    switch (button) {
    case Qt::LeftButton:
        return press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
    case Qt::RightButton:
        return press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
    case Qt::MiddleButton:
        return press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
    default:
        return std::nullopt;
    }
}

} // namespace

std::optional<QPointF> ToolpathView::widgetPositionOf(std::size_t passIndex) {
    const std::optional<std::size_t> drawn = drawnPointOf(passIndex);
    if (!drawn) {
        return std::nullopt;
    }
    syncViewport();
    vtkRenderer* renderer = m_vtk->renderer;
    const Vec3& p = m_vtk->scene.tips[*drawn];
    renderer->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
    renderer->WorldToDisplay();
    const double* display = renderer->GetDisplayPoint();
    // Display y runs up from the bottom row, as in forward()'s flip.
    return QPointF(display[0], renderSize().height() - 1 - display[1]);
}

// The ray through the click hits the blade or the path first; the drawn path point nearest
// that hit is picked, if it lies within kPickRadiusPx of the click on screen.
std::optional<std::size_t> ToolpathView::pickAt(QPointF position) {
    Scene& vtk = *m_vtk;
    if (!vtk.hasData || !sceneArea().contains(position.toPoint())) {
        return std::nullopt;
    }
    syncViewport();
    const double displayY = renderSize().height() - 1 - position.y();
    if (vtk.picker->Pick(position.x(), displayY, 0.0, vtk.renderer) == 0) {
        return std::nullopt;
    }
    double hit[3] = {0.0, 0.0, 0.0};
    vtk.picker->GetPickPosition(hit);
    const Vec3 world(hit[0], hit[1], hit[2]);
    const std::vector<Vec3>& tips = vtk.scene.tips;
    std::size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < tips.size(); ++i) {
        const double distance = (tips[i] - world).squaredNorm();
        if (distance < best) {
            best = distance;
            nearest = i;
        }
    }
    const std::size_t record = vtk.scene.record[nearest];
    const std::optional<QPointF> shown = widgetPositionOf(record);
    if (!shown ||
        std::hypot(shown->x() - position.x(), shown->y() - position.y()) > kPickRadiusPx) {
        return std::nullopt; // the blade where the path does not run
    }
    return record;
}

void ToolpathView::forward(QMouseEvent* event, unsigned long vtkEvent) {
    const QPointF position = event->position();
    syncViewport();
    m_vtk->interactor->SetEventInformationFlipY(static_cast<int>(position.x()),
                                                static_cast<int>(position.y()),
                                                (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                                (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
    m_vtk->interactor->InvokeEvent(vtkEvent, nullptr);
    update();
}

void ToolpathView::mousePressEvent(QMouseEvent* event) {
    if (!QRect(QPoint(0, 0), renderSize()).contains(event->position().toPoint())) {
        event->ignore(); // the control strip's empty space
        return;
    }
    if (event->button() == Qt::LeftButton) {
        m_pressPosition = event->position();
    }
    if (const std::optional<unsigned long> vtkEvent = vtkButtonEvent(event->button(), true)) {
        forward(event, *vtkEvent);
    }
}

void ToolpathView::mouseReleaseEvent(QMouseEvent* event) {
    if (const std::optional<unsigned long> vtkEvent = vtkButtonEvent(event->button(), false)) {
        forward(event, *vtkEvent);
    }
    const bool click = event->button() == Qt::LeftButton &&
                       (event->position() - m_pressPosition).manhattanLength() <= kClickSlopPx;
    if (click) {
        if (const std::optional<std::size_t> record = pickAt(event->position())) {
            emit pointPicked(*record);
        }
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

} // namespace bladeaxis::ui

#include "ui/s_theta_editor.h"

#include "core/scheduling/layer_edit.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <utility>

namespace bladeaxis::ui {
namespace {

constexpr double kMargin = 30.0;
constexpr double kPickRadius = 8.0;

} // namespace

SThetaEditor::SThetaEditor(QWidget* parent) : QWidget(parent) {
    setMinimumSize(320, 200);
    setMouseTracking(false);
    setToolTip(tr("Drag a key point to re-shape theta(S); double-click adds a key point, "
                  "right-click deletes one. Ctrl+Z undoes. The job re-runs with the edit."));
}

void SThetaEditor::setLayer(const scheduling::LayerResult& layer,
                            const scheduling::ScheduleParameters& parameters) {
    m_layer = layer;
    m_parameters = parameters;
    m_refusal.clear();
    m_pending.clear();
    m_thetaLow = layer.thetaMin.empty() ? 0.0 : std::ranges::min(layer.thetaMin);
    m_thetaHigh = layer.thetaMax.empty() ? 1.0 : std::ranges::max(layer.thetaMax);
    if (m_thetaHigh <= m_thetaLow) {
        m_thetaHigh = m_thetaLow + 1.0;
    }
    update();
}

void SThetaEditor::clearLayer() {
    m_layer.reset();
    m_pending.clear();
    update();
}

void SThetaEditor::setPending(const QString& message) {
    m_pending = message;
    update();
}

QPointF SThetaEditor::toWidget(double s, double theta) const {
    const double s0 = m_layer->s.front();
    const double s1 = std::max(m_layer->s.back(), s0 + 1e-9);
    const double x = kMargin + (s - s0) / (s1 - s0) * (width() - 2.0 * kMargin);
    const double y = height() - kMargin -
                     (theta - m_thetaLow) / (m_thetaHigh - m_thetaLow) * (height() - 2.0 * kMargin);
    return {x, y};
}

Vec2 SThetaEditor::fromWidget(QPointF point) const {
    const double s0 = m_layer->s.front();
    const double s1 = std::max(m_layer->s.back(), s0 + 1e-9);
    const double s = s0 + (point.x() - kMargin) / (width() - 2.0 * kMargin) * (s1 - s0);
    const double theta = m_thetaLow + (height() - kMargin - point.y()) /
                                          (height() - 2.0 * kMargin) * (m_thetaHigh - m_thetaLow);
    return {s, theta};
}

QPointF SThetaEditor::vertexPosition(std::size_t index) const {
    const Vec2& vertex = m_layer->polyline.at(index);
    return toWidget(vertex.x(), vertex.y());
}

std::optional<std::size_t> SThetaEditor::vertexNear(QPointF point) const {
    if (!m_layer) {
        return std::nullopt;
    }
    for (std::size_t i = 0; i < m_layer->polyline.size(); ++i) {
        const QPointF delta = vertexPosition(i) - point;
        if (QPointF::dotProduct(delta, delta) <= kPickRadius * kPickRadius) {
            return i;
        }
    }
    return std::nullopt;
}

bool SThetaEditor::applyVertices(const std::vector<Vec2>& vertices) {
    if (!m_layer) {
        return false;
    }
    Result<scheduling::LayerResult> edited =
        scheduling::resmoothLayer(*m_layer, vertices, m_parameters);
    if (!edited) {
        m_refusal = QString::fromStdString(edited.error().message);
        update();
        return false;
    }
    m_refusal.clear();
    m_layer = std::move(*edited);
    update();
    emit layerEdited();
    return true;
}

void SThetaEditor::finishEdit(std::vector<Vec2> before, std::vector<Vec2> after,
                              const QString& text) {
    emit keyPointsEdited(before, after, text);
}

void SThetaEditor::mousePressEvent(QMouseEvent* event) {
    if (!m_layer) {
        return;
    }
    const std::optional<std::size_t> vertex = vertexNear(event->position());
    const bool interior = vertex && *vertex > 0 && *vertex + 1 < m_layer->polyline.size();
    if (!interior) {
        return;
    }
    if (event->button() == Qt::RightButton) {
        std::vector<Vec2> before = m_layer->polyline;
        std::vector<Vec2> after = before;
        after.erase(after.begin() + static_cast<std::ptrdiff_t>(*vertex));
        if (applyVertices(after)) { // else it shows the refusal
            finishEdit(std::move(before), std::move(after), tr("Delete key point"));
        }
        return;
    }
    m_dragged = vertex;
    m_dragStart = m_layer->polyline;
}

void SThetaEditor::mouseMoveEvent(QMouseEvent* event) {
    if (!m_dragged || !m_layer) {
        return;
    }
    std::vector<Vec2> moved = m_layer->polyline;
    moved[*m_dragged] = fromWidget(event->position());
    applyVertices(moved);
}

void SThetaEditor::mouseReleaseEvent(QMouseEvent* event) {
    if (!m_dragged || !m_layer) {
        return;
    }
    mouseMoveEvent(event);
    m_dragged.reset();
    if (m_layer->polyline != m_dragStart) {
        std::vector<Vec2> after = m_layer->polyline;
        finishEdit(std::exchange(m_dragStart, {}), std::move(after), tr("Move key point"));
    }
}

void SThetaEditor::mouseDoubleClickEvent(QMouseEvent* event) {
    if (!m_layer) {
        return;
    }
    const Vec2 point = fromWidget(event->position());
    std::vector<Vec2> before = m_layer->polyline;
    std::vector<Vec2> after = before;
    const auto at = std::upper_bound(after.begin(), after.end(), point,
                                     [](const Vec2& a, const Vec2& b) { return a.x() < b.x(); });
    after.insert(at, point);
    if (applyVertices(after)) {
        finishEdit(std::move(before), std::move(after), tr("Add key point"));
    }
}

void SThetaEditor::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    if (!m_layer || m_layer->s.empty()) {
        painter.setPen(palette().text().color());
        painter.drawText(rect(), Qt::AlignCenter, tr("Select a layer"));
        return;
    }
    paintBands(painter);
    paintCurves(painter);
    paintMessages(painter);
}

// Raw channel (blue) and monotone hull (green) as bands.
void SThetaEditor::paintBands(QPainter& painter) const {
    const auto& l = *m_layer;
    auto bandOf = [&](const std::vector<double>& low, const std::vector<double>& high) {
        QPolygonF polygon;
        for (std::size_t i = 0; i < l.s.size(); ++i) {
            polygon << toWidget(l.s[i], high[i]);
        }
        for (std::size_t i = l.s.size(); i-- > 0;) {
            polygon << toWidget(l.s[i], low[i]);
        }
        return polygon;
    };
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(120, 160, 220, 70));
    painter.drawPolygon(bandOf(l.thetaMin, l.thetaMax));
    painter.setBrush(QColor(80, 180, 120, 90));
    painter.drawPolygon(bandOf(l.lo, l.hi));
}

// Original theta(S) dashed, the polyline with its key points, the smoothed theta(S) in red.
void SThetaEditor::paintCurves(QPainter& painter) const {
    const auto& l = *m_layer;
    auto curveOf = [&](const std::vector<double>& theta) {
        QPolygonF polygon;
        for (std::size_t i = 0; i < l.s.size() && i < theta.size(); ++i) {
            polygon << toWidget(l.s[i], theta[i]);
        }
        return polygon;
    };
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(150, 150, 150), 1.0, Qt::DashLine));
    painter.drawPolyline(curveOf(l.thetaOriginal));
    painter.setPen(QPen(QColor(230, 140, 30), 1.0));
    QPolygonF polyline;
    for (const Vec2& vertex : l.polyline) {
        polyline << toWidget(vertex.x(), vertex.y());
    }
    painter.drawPolyline(polyline);
    painter.setPen(QPen(QColor(200, 40, 40), 2.0));
    painter.drawPolyline(curveOf(l.theta));
    painter.setBrush(QColor(230, 140, 30));
    for (const QPointF& point : polyline) {
        painter.drawEllipse(point, 4.0, 4.0);
    }
}

void SThetaEditor::paintMessages(QPainter& painter) const {
    painter.setBrush(Qt::NoBrush);
    if (!m_refusal.isEmpty()) {
        painter.setPen(QPen(Qt::red, 3.0));
        painter.drawRect(rect().adjusted(1, 1, -2, -2));
        painter.drawText(QPointF(kMargin, kMargin - 8.0), tr("Refused: %1").arg(m_refusal));
    } else if (!m_pending.isEmpty()) {
        painter.setPen(palette().text().color());
        painter.drawText(QPointF(kMargin, kMargin - 8.0), m_pending);
    }
}

} // namespace bladeaxis::ui

#include "ui/s_theta_editor.h"

#include "core/base/units.h"
#include "core/scheduling/layer_edit.h"

#include <QFontMetricsF>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <utility>

namespace bladeaxis::ui {
namespace {

constexpr double kMargin = 44.0; // room for the tick labels
constexpr int kTicks = 5;
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
    paintAxes(painter);
    paintBands(painter);
    paintCurves(painter);
    paintLegend(painter);
    paintMessages(painter);
}

// S in mm along the bottom, theta in degrees (relative to the layer start) up the left side.
void SThetaEditor::paintAxes(QPainter& painter) const {
    const auto& l = *m_layer;
    const QColor text = palette().text().color();
    painter.setPen(QPen(palette().mid().color(), 1.0));
    const QPointF origin = toWidget(l.s.front(), m_thetaLow);
    const QPointF xEnd = toWidget(l.s.back(), m_thetaLow);
    const QPointF yEnd = toWidget(l.s.front(), m_thetaHigh);
    painter.drawLine(origin, xEnd);
    painter.drawLine(origin, yEnd);
    painter.setPen(text);
    const QFontMetricsF metrics(painter.font());
    for (int k = 0; k <= kTicks; ++k) {
        const double f = static_cast<double>(k) / kTicks;
        const double s = l.s.front() + f * (l.s.back() - l.s.front());
        const QPointF x = toWidget(s, m_thetaLow);
        const QString sLabel = QString::number(s, 'f', 0);
        painter.drawLine(x, x + QPointF(0.0, 4.0));
        painter.drawText(x + QPointF(-0.5 * metrics.horizontalAdvance(sLabel), 16.0), sLabel);
        const double theta = m_thetaLow + f * (m_thetaHigh - m_thetaLow);
        const QPointF y = toWidget(l.s.front(), theta);
        const QString thetaLabel = QString::number(units::radToDeg(theta), 'f', 0);
        painter.drawLine(y, y - QPointF(4.0, 0.0));
        painter.drawText(y + QPointF(-6.0 - metrics.horizontalAdvance(thetaLabel), 4.0),
                         thetaLabel);
    }
    painter.drawText(QPointF(width() - kMargin - 40.0, height() - 4.0), tr("S [mm]"));
    painter.drawText(QPointF(4.0, kMargin - 24.0), tr("θ [°]"));
}

void SThetaEditor::paintLegend(QPainter& painter) const {
    struct Entry {
        QString name;
        QColor colour;
        bool band;
    };
    const Entry entries[] = {{tr("raw channel"), QColor(120, 160, 220, 110), true},
                             {tr("monotone hull"), QColor(80, 180, 120, 140), true},
                             {tr("original θ"), QColor(150, 150, 150), false},
                             {tr("key points"), QColor(230, 140, 30), false},
                             {tr("scheduled θ"), QColor(200, 40, 40), false}};
    double y = kMargin + 4.0;
    const double x = width() - kMargin - 110.0;
    for (const Entry& entry : entries) {
        if (entry.band) {
            painter.fillRect(QRectF(x, y - 8.0, 18.0, 10.0), entry.colour);
        } else {
            painter.setPen(QPen(entry.colour, 2.0));
            painter.drawLine(QPointF(x, y - 3.0), QPointF(x + 18.0, y - 3.0));
        }
        painter.setPen(palette().text().color());
        painter.drawText(QPointF(x + 24.0, y + 1.0), entry.name);
        y += 15.0;
    }
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

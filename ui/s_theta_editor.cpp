#include "ui/s_theta_editor.h"

#include "core/base/units.h"
#include "core/scheduling/layer_edit.h"
#include "ui/axis_ticks.h"

#include <QEvent>
#include <QFontMetricsF>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <algorithm>
#include <utility>

namespace bladeaxis::ui {
namespace {

constexpr double kPickRadius = 8.0;
constexpr double kGap = 6.0; // between the frame, labels and strips
// The message strip is as high as this message, as long as the editor's longest refusal, needs
// at the editor's width: the strip changes with the width only, not when a message appears.
const char* const kLongestMessage =
    "Layer 000 refused: the segment from key point 000 to key point 000 leaves the channel by "
    "000.00 deg at S = 0000.00 mm";

const QColor kRawChannel(120, 160, 220, 110);
const QColor kHull(80, 180, 120, 140);
const QColor kOriginal(150, 150, 150);
const QColor kKeyPoints(230, 140, 30);
const QColor kScheduled(200, 40, 40);

struct LegendEntry {
    QString name;
    QColor colour;
    enum class Style { Band, Line, Dashed, Points } style;
};

std::vector<LegendEntry> legendEntries() {
    return {{SThetaEditor::tr("raw channel"), kRawChannel, LegendEntry::Style::Band},
            {SThetaEditor::tr("monotone hull"), kHull, LegendEntry::Style::Band},
            {SThetaEditor::tr("original θ"), kOriginal, LegendEntry::Style::Dashed},
            {SThetaEditor::tr("key points"), kKeyPoints, LegendEntry::Style::Points},
            {SThetaEditor::tr("scheduled θ"), kScheduled, LegendEntry::Style::Line}};
}

constexpr double kSwatch = 18.0;

double entryWidth(const LegendEntry& entry, const QFontMetricsF& metrics) {
    return kSwatch + 6.0 + metrics.horizontalAdvance(entry.name) + 14.0;
}

// The legend's rows when laid out left to right in `width`: the entries of each row.
std::vector<std::vector<LegendEntry>> legendRows(double width, const QFontMetricsF& metrics) {
    std::vector<std::vector<LegendEntry>> rows(1);
    double used = 0.0;
    for (const LegendEntry& entry : legendEntries()) {
        const double w = entryWidth(entry, metrics);
        if (used > 0.0 && used + w > width) {
            rows.emplace_back();
            used = 0.0;
        }
        rows.back().push_back(entry);
        used += w;
    }
    return rows;
}

} // namespace

SThetaEditor::SThetaEditor(QWidget* parent) : QWidget(parent) {
    setMinimumSize(320, 200);
    setMouseTracking(true); // the hover readout
    // A click on the plot takes the focus from a settings box, so Ctrl+Z then undoes the job's
    // last edit rather than the box's typing.
    setFocusPolicy(Qt::ClickFocus);
    setToolTip(tr("Drag a key point to re-shape theta(S); double-click adds a key point, "
                  "right-click deletes one. Ctrl+Z undoes. The job re-runs with the edit."));
}

void SThetaEditor::setLayer(const scheduling::LayerResult& layer,
                            const scheduling::ScheduleParameters& parameters, std::size_t number) {
    m_layer = layer;
    m_layerNumber = number;
    m_parameters = parameters;
    m_refusal.clear();
    m_pending.clear();
    m_thetaLow = layer.thetaMin.empty() ? 0.0 : std::ranges::min(layer.thetaMin);
    m_thetaHigh = layer.thetaMax.empty() ? 1.0 : std::ranges::max(layer.thetaMax);
    if (m_thetaHigh <= m_thetaLow) {
        m_thetaHigh = m_thetaLow + 1.0;
    }
    relayout(); // the message strip may have gone
}

void SThetaEditor::clearLayer() {
    m_layer.reset();
    m_pending.clear();
    relayout();
}

void SThetaEditor::setPending(const QString& message) {
    m_pending = message;
    relayout();
}

QString SThetaEditor::message() const {
    return !m_refusal.isEmpty() ? tr("Layer %1 refused: %2").arg(m_layerNumber).arg(m_refusal)
                                : m_pending;
}

// The strips above the data: the legend (wrapped to the width), then the refusal or pending
// message (wrapped); below them the plot with room for the tick labels left and under it.
// Worked out once per change of size, font or message, not at every point drawn.
void SThetaEditor::relayout() {
    const QFontMetricsF metrics(font());
    m_legendHeight = static_cast<double>(legendRows(width() - 2.0 * kGap, metrics).size()) *
                         (metrics.height() + 2.0) +
                     kGap;
    const QRectF available(kGap, m_legendHeight, width() - 2.0 * kGap, height());
    double messageHeight =
        metrics
            .boundingRect(available, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop,
                          QString::fromLatin1(kLongestMessage))
            .height();
    if (const QString text = message(); !text.isEmpty()) {
        const QRectF needed =
            metrics.boundingRect(available, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, text);
        messageHeight = std::max(messageHeight, needed.height());
    }
    m_messageRect =
        QRectF(available.left(), available.top(), available.width(), messageHeight + kGap);
    const double left = metrics.horizontalAdvance(QStringLiteral("-0000")) + 2.0 * kGap;
    const double top = m_legendHeight + m_messageRect.height() + metrics.height() + kGap;
    const double bottom = 2.0 * metrics.height() + kGap;
    m_plotArea = QRectF(left, top, std::max(width() - left - 2.0 * kGap, 10.0),
                        std::max(height() - top - bottom, 10.0));
    update();
}

void SThetaEditor::resizeEvent(QResizeEvent*) {
    relayout();
}

void SThetaEditor::changeEvent(QEvent* event) {
    if (event->type() == QEvent::FontChange) {
        relayout();
    }
    QWidget::changeEvent(event);
}

QPointF SThetaEditor::toWidget(double s, double theta) const {
    const QRectF plot = plotArea();
    const double s0 = m_layer->s.front();
    const double s1 = std::max(m_layer->s.back(), s0 + 1e-9);
    const double x = plot.left() + (s - s0) / (s1 - s0) * plot.width();
    const double y =
        plot.bottom() - (theta - m_thetaLow) / (m_thetaHigh - m_thetaLow) * plot.height();
    return {x, y};
}

Vec2 SThetaEditor::fromWidget(QPointF point) const {
    const QRectF plot = plotArea();
    const double s0 = m_layer->s.front();
    const double s1 = std::max(m_layer->s.back(), s0 + 1e-9);
    const double s = s0 + (point.x() - plot.left()) / plot.width() * (s1 - s0);
    const double theta =
        m_thetaLow + (plot.bottom() - point.y()) / plot.height() * (m_thetaHigh - m_thetaLow);
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
        relayout();
        return false;
    }
    const bool hadRefusal = !m_refusal.isEmpty();
    m_refusal.clear();
    m_layer = std::move(*edited);
    hadRefusal ? relayout() : update();
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
    if (m_layer && !m_dragged) {
        const QString readout = readoutAt(event->position());
        if (!readout.isEmpty()) {
            QToolTip::showText(event->globalPosition().toPoint(), readout, this);
        } else {
            QToolTip::hideText();
        }
        return;
    }
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

// S in mm along the bottom, theta in degrees (relative to the layer start) up the left side,
// both at round values.
void SThetaEditor::paintAxes(QPainter& painter) const {
    const auto& l = *m_layer;
    const QRectF plot = plotArea();
    const QFontMetricsF metrics(painter.font());
    const QColor text = palette().text().color();
    const QColor grid = palette().mid().color();
    painter.setPen(QPen(grid, 1.0));
    painter.drawRect(plot);
    const int sTicks = std::max(2, static_cast<int>(plot.width() / 70.0));
    for (double s : niceTicks(l.s.front(), l.s.back(), sTicks)) {
        const QPointF x = toWidget(s, m_thetaLow);
        const QString label = tickLabel(s, niceStep(l.s.back() - l.s.front(), sTicks));
        painter.setPen(QPen(grid, 1.0));
        painter.drawLine(x, x + QPointF(0.0, 4.0));
        painter.setPen(text);
        painter.drawText(QRectF(x.x() - 40.0, plot.bottom() + 4.0, 80.0, metrics.height()),
                         Qt::AlignHCenter | Qt::AlignTop, label);
    }
    const double lowDeg = units::radToDeg(m_thetaLow), highDeg = units::radToDeg(m_thetaHigh);
    const int thetaTicks = std::max(2, static_cast<int>(plot.height() / (2.0 * metrics.height())));
    for (double degrees : niceTicks(lowDeg, highDeg, thetaTicks)) {
        const QPointF y = toWidget(l.s.front(), units::degToRad(degrees));
        painter.setPen(QPen(grid, 1.0));
        painter.drawLine(y, y - QPointF(4.0, 0.0));
        painter.setPen(text);
        painter.drawText(
            QRectF(0.0, y.y() - metrics.height() / 2, plot.left() - kGap, metrics.height()),
            Qt::AlignRight | Qt::AlignVCenter,
            tickLabel(degrees, niceStep(highDeg - lowDeg, thetaTicks)));
    }
    painter.drawText(
        QRectF(plot.left(), plot.bottom() + metrics.height() + 4.0, plot.width(), metrics.height()),
        Qt::AlignRight | Qt::AlignTop, tr("S [mm]"));
    painter.drawText(
        QRectF(kGap, plot.top() - metrics.height() - 2.0, plot.width(), metrics.height()),
        Qt::AlignLeft | Qt::AlignBottom, tr("θ [°]"));
}

// Above the data, never over it: a row (or rows) of swatches and names.
void SThetaEditor::paintLegend(QPainter& painter) const {
    const QFontMetricsF metrics(painter.font());
    double y = kGap / 2;
    for (const auto& row : legendRows(width() - 2.0 * kGap, metrics)) {
        double x = kGap;
        const double middle = y + metrics.height() / 2;
        for (const LegendEntry& entry : row) {
            switch (entry.style) {
            case LegendEntry::Style::Band:
                painter.fillRect(QRectF(x, middle - 5.0, kSwatch, 10.0), entry.colour);
                break;
            case LegendEntry::Style::Points:
                painter.setPen(Qt::NoPen);
                painter.setBrush(entry.colour);
                painter.drawEllipse(QPointF(x + kSwatch / 2, middle), 4.0, 4.0);
                painter.setBrush(Qt::NoBrush);
                break;
            default:
                painter.setPen(
                    QPen(entry.colour, 2.0,
                         entry.style == LegendEntry::Style::Dashed ? Qt::DashLine : Qt::SolidLine));
                painter.drawLine(QPointF(x, middle), QPointF(x + kSwatch, middle));
            }
            painter.setPen(palette().text().color());
            painter.drawText(QRectF(x + kSwatch + 6.0, y, width(), metrics.height()),
                             Qt::AlignLeft | Qt::AlignVCenter, entry.name);
            x += entryWidth(entry, metrics);
        }
        y += metrics.height() + 2.0;
    }
}

QStringList SThetaEditor::legendNames() const {
    QStringList names;
    for (const LegendEntry& entry : legendEntries()) {
        names << entry.name;
    }
    return names;
}

// S, the original and the scheduled theta at the mouse's S, and the channel there.
QString SThetaEditor::readoutAt(QPointF position) const {
    if (!m_layer || m_layer->s.size() < 2 || !plotArea().contains(position)) {
        return {};
    }
    const auto& l = *m_layer;
    const double s = std::clamp(fromWidget(position).x(), l.s.front(), l.s.back());
    const auto after = std::lower_bound(l.s.begin(), l.s.end(), s);
    const auto i = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(after - l.s.begin(), 0, std::ssize(l.s) - 1));
    auto degrees = [&](const std::vector<double>& values) {
        return i < values.size() ? QLocale().toString(units::radToDeg(values[i]), 'f', 2)
                                 : QStringLiteral("–");
    };
    return tr("S %1 mm\nscheduled θ %2°\noriginal θ %3°\nchannel %4° … %5°")
        .arg(QLocale().toString(l.s[i], 'f', 1), degrees(l.theta), degrees(l.thetaOriginal),
             degrees(l.thetaMin), degrees(l.thetaMax));
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
    painter.setBrush(kRawChannel);
    painter.drawPolygon(bandOf(l.thetaMin, l.thetaMax));
    painter.setBrush(kHull);
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
    painter.save();
    painter.setClipRect(
        plotArea().adjusted(-6.0, -6.0, 6.0, 6.0)); // key points may sit on the edge
    painter.setPen(QPen(kOriginal, 1.0, Qt::DashLine));
    painter.drawPolyline(curveOf(l.thetaOriginal));
    painter.setPen(QPen(kKeyPoints, 1.0));
    QPolygonF polyline;
    for (const Vec2& vertex : l.polyline) {
        polyline << toWidget(vertex.x(), vertex.y());
    }
    painter.drawPolyline(polyline);
    painter.setPen(QPen(kScheduled, 2.0));
    painter.drawPolyline(curveOf(l.theta));
    painter.setBrush(kKeyPoints);
    for (const QPointF& point : polyline) {
        painter.drawEllipse(point, 4.0, 4.0);
    }
    painter.restore();
}

// The whole refusal or pending message, wrapped in its own strip above the plot (kept while no
// message is shown, so the plot stays where it is), never cut off.
void SThetaEditor::paintMessages(QPainter& painter) const {
    const QRectF strip = messageRect();
    if (message().isEmpty()) {
        return;
    }
    painter.setBrush(Qt::NoBrush);
    if (!m_refusal.isEmpty()) {
        painter.setPen(QPen(QColor(210, 30, 30), 3.0));
        painter.drawRect(rect().adjusted(1, 1, -2, -2));
    }
    painter.setPen(m_refusal.isEmpty() ? palette().text().color() : QColor(210, 30, 30));
    painter.drawText(strip, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, message());
}

} // namespace bladeaxis::ui

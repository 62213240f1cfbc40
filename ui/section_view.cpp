#include "ui/section_view.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace bladeaxis::ui {
namespace {

constexpr std::size_t kGlyphsPerLayer = 36;

const QColor kOriginalColour(235, 140, 40);
const QColor kRescheduledColour(30, 160, 220);
const QColor kCentreColour(120, 120, 130);

QPointF inPlane(const Vec3& point) {
    return {point.y(), point.z()};
}

// The in-plane direction of a tool axis: its angle is the schedule's theta.
QPointF inPlaneDirection(const Vec3& axis) {
    const double length = std::hypot(axis.y(), axis.z());
    return length > 0.0 ? QPointF(axis.y() / length, axis.z() / length) : QPointF();
}

} // namespace

SectionView::SectionView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(240, 200);
    setToolTip(tr("The selected layer in its section plane: blade section, ball-centre path, "
                  "tool axes original (orange) and re-scheduled (blue)"));
}

void SectionView::clearLayer() {
    m_layer = -1;
    m_section.clear();
    m_centres.clear();
    m_glyphs.clear();
    update();
}

void SectionView::setLayer(const job::DisplayScene& scene, int layer) {
    if (layer < 0 || static_cast<std::size_t>(layer) >= scene.layers.size()) {
        clearLayer();
        return;
    }
    const job::DisplayLayer& shown = scene.layers[static_cast<std::size_t>(layer)];
    m_layer = layer;
    m_sectionX = shown.sectionX;
    m_toolRadius = scene.toolRadius;
    m_surfaceName = QString::fromStdString(scene.surfaceName);
    m_section.clear();
    for (const cad::Polyline3& piece : shown.section) {
        std::vector<QPointF> points;
        points.reserve(piece.points.size() + 1);
        for (const Vec3& p : piece.points) {
            points.push_back(inPlane(p));
        }
        if (piece.closed && !points.empty()) {
            points.push_back(points.front());
        }
        m_section.push_back(std::move(points));
    }
    m_centres.clear();
    for (std::size_t i = shown.firstPoint; i <= shown.lastPoint && i < scene.centres.size(); ++i) {
        m_centres.push_back(inPlane(scene.centres[i]));
    }
    m_glyphs.clear();
    const std::size_t count = shown.lastPoint - shown.firstPoint + 1;
    const std::size_t stride = std::max<std::size_t>(count / kGlyphsPerLayer, 1);
    for (std::size_t i = shown.firstPoint; i <= shown.lastPoint && i < scene.centres.size();
         i += stride) {
        Glyph glyph;
        glyph.centre = inPlane(scene.centres[i]);
        glyph.original = inPlaneDirection(scene.originalAxes[i]);
        if (scene.hasRescheduled()) {
            glyph.rescheduled = inPlaneDirection(scene.rescheduledAxes[i]);
        }
        m_glyphs.push_back(glyph);
    }
    update();
}

// The section and the ball centres, without the tool-axis glyphs.
QRectF SectionView::pathBounds() const {
    QRectF bounds;
    const auto include = [&bounds](const QPointF& p) {
        bounds = bounds.isNull() ? QRectF(p, QSizeF(1e-9, 1e-9))
                                 : bounds.united(QRectF(p, QSizeF(1e-9, 1e-9)));
    };
    for (const auto& piece : m_section) {
        std::for_each(piece.begin(), piece.end(), include);
    }
    std::for_each(m_centres.begin(), m_centres.end(), include);
    return bounds;
}

// Axes long enough to read the angle: 2.5 R, or 6 % of the section where R is small beside it.
double SectionView::glyphLength() const {
    const QRectF path = pathBounds();
    return std::max(2.5 * m_toolRadius, 0.06 * std::max(path.width(), path.height()));
}

// Everything drawn, glyphs at the length they are drawn with, so nothing runs past the pane.
QRectF SectionView::contentBounds() const {
    QRectF bounds = pathBounds();
    const double length = glyphLength();
    for (const Glyph& glyph : m_glyphs) {
        for (const QPointF& end :
             {glyph.centre + length * glyph.original, glyph.centre + length * glyph.rescheduled}) {
            bounds = bounds.united(QRectF(end, QSizeF(1e-9, 1e-9)));
        }
    }
    const double margin = 0.03 * std::max(bounds.width(), bounds.height());
    return bounds.adjusted(-margin, -margin, margin, margin);
}

void SectionView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base()); // follows the light or dark palette
    painter.setClipRect(rect());
    if (m_layer < 0) {
        painter.setPen(palette().text().color());
        painter.drawText(rect(), Qt::AlignCenter, tr("Select a layer to see its section"));
        return;
    }
    // Uniform scale, y to the right and z up, centred.
    const QRectF content = contentBounds();
    const QRectF area = QRectF(rect()).adjusted(12, 34, -12, -12);
    const double scale = std::min(area.width() / content.width(), area.height() / content.height());
    const QPointF middle = content.center();
    const auto toScreen = [&](const QPointF& p) {
        return QPointF(area.center().x() + (p.x() - middle.x()) * scale,
                       area.center().y() - (p.y() - middle.y()) * scale);
    };

    for (const auto& piece : m_section) {
        QPainterPath path;
        for (std::size_t i = 0; i < piece.size(); ++i) {
            i == 0 ? path.moveTo(toScreen(piece[i])) : path.lineTo(toScreen(piece[i]));
        }
        painter.setPen(QPen(palette().color(QPalette::Text), 2.0));
        painter.setBrush(QColor(200, 205, 215)); // light metal, readable on both palettes
        painter.drawPath(path);
    }
    painter.setBrush(Qt::NoBrush);
    if (m_centres.size() >= 2) {
        QPainterPath path;
        path.moveTo(toScreen(m_centres.front()));
        for (std::size_t i = 1; i < m_centres.size(); ++i) {
            path.lineTo(toScreen(m_centres[i]));
        }
        painter.setPen(QPen(kCentreColour, 1.2, Qt::DashLine));
        painter.drawPath(path);
    }
    // Axes from the ball centre away from the blade.
    const double length = glyphLength();
    for (const Glyph& glyph : m_glyphs) {
        const QPointF start = toScreen(glyph.centre);
        painter.setPen(QPen(kOriginalColour, 1.6));
        painter.drawLine(start, toScreen(glyph.centre + length * glyph.original));
        if (!glyph.rescheduled.isNull()) {
            painter.setPen(QPen(kRescheduledColour, 1.6));
            painter.drawLine(start, toScreen(glyph.centre + length * glyph.rescheduled));
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(kCentreColour);
        painter.drawEllipse(start, 2.0, 2.0);
        painter.setBrush(Qt::NoBrush);
    }

    // The title on the left, elided before it reaches the legend on the right.
    const QFontMetricsF metrics(painter.font());
    const QRectF top = QRectF(rect()).adjusted(8, 6, -8, 0);
    const double legendWidth = std::max(metrics.horizontalAdvance(tr("original")),
                                        metrics.horizontalAdvance(tr("re-scheduled"))) +
                               12.0;
    painter.setPen(palette().color(QPalette::Text));
    const QString title = tr("Layer %1, section x = %2 mm (%3)")
                              .arg(m_layer)
                              .arg(m_sectionX, 0, 'f', 2)
                              .arg(m_surfaceName);
    painter.drawText(top.adjusted(0, 0, -legendWidth, 0), Qt::AlignLeft | Qt::AlignTop,
                     metrics.elidedText(title, Qt::ElideRight, top.width() - legendWidth));
    painter.setPen(kOriginalColour);
    painter.drawText(top, Qt::AlignRight | Qt::AlignTop, tr("original"));
    painter.setPen(kRescheduledColour);
    painter.drawText(top.adjusted(0, metrics.height(), 0, 0), Qt::AlignRight | Qt::AlignTop,
                     tr("re-scheduled"));
}

} // namespace bladeaxis::ui

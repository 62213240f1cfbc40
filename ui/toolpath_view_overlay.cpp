// The legend band of the 3D view: every colour drawn and what it means, the speed colour bar
// and the axes marker, painted by Qt over the rendered frame.
#include "core/base/units.h"
#include "ui/toolpath_view.h"
#include "ui/toolpath_view_scene.h"

#include <QLinearGradient>
#include <QPainter>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkUnsignedCharArray.h>

namespace bladeaxis::ui {

using namespace detail;

namespace {

using Swatch = ToolpathView::LegendEntry::Swatch;

// The sample beside a legend entry, in `box` (the swatch column of its first text line).
void paintSwatch(QPainter& painter, const ToolpathView::LegendEntry& entry, const QRectF& box) {
    const double y = box.center().y();
    const auto line = [&](const QColor& colour, double width, double from, double to) {
        painter.setPen(QPen(colour, width, Qt::SolidLine, Qt::FlatCap));
        painter.drawLine(QPointF(box.left() + from * box.width(), y),
                         QPointF(box.left() + to * box.width(), y));
    };
    switch (entry.swatch) {
    case Swatch::Line:
        line(entry.colour, 2.0, 0.0, 1.0);
        break;
    case Swatch::ThickLine:
        line(entry.colour, 5.0, 0.0, 1.0);
        break;
    case Swatch::ThickSpeed:
        for (int step = 0; step < 4; ++step) {
            line(speedColour(step / 3.0), 5.0, step / 4.0, (step + 1) / 4.0);
        }
        break;
    case Swatch::Palette:
    case Swatch::DimmedPalette:
        for (std::size_t k = 0; k < kLayerPalette.size(); ++k) {
            const double third = 1.0 / static_cast<double>(kLayerPalette.size());
            const double from = static_cast<double>(k) * third;
            line(entry.swatch == Swatch::Palette ? layerColour(k) : dimmedLayerColour(k), 2.0, from,
                 from + third);
        }
        break;
    case Swatch::Area:
        painter.fillRect(QRectF(box.left(), y - 5.0, box.width(), 10.0), entry.colour);
        break;
    case Swatch::ColourBar:
        break; // drawn below its title, across the band
    }
}

} // namespace

QString ToolpathView::colourBarTitle() const {
    const job::DisplayScene& scene = m_vtk->scene;
    if (m_colouring == Colouring::Layer || scene.aSpeedOriginal.empty()) {
        return {};
    }
    const bool original =
        m_colouring == Colouring::OriginalASpeed || scene.aSpeedRescheduled.empty();
    // The speeds stay rad/s inside; degrees are what the engineer reads everywhere else.
    return (original ? tr("|d%1/dt| original (deg/s)") : tr("|d%1/dt| re-scheduled (deg/s)"))
        .arg(m_tableLetter);
}

std::vector<ToolpathView::LegendEntry> ToolpathView::legend() const {
    const job::DisplayScene& scene = m_vtk->scene;
    std::vector<LegendEntry> entries;
    const QString bar = colourBarTitle();
    if (!bar.isEmpty()) {
        entries.push_back({bar, speedColour(1.0), Swatch::ColourBar});
        if (m_selected >= 0) {
            entries.push_back(
                {tr("layer %1 (selected)").arg(m_selected), QColor(), Swatch::ThickSpeed});
        }
    } else if (m_selected >= 0) {
        entries.push_back(
            {tr("layer %1 (selected)").arg(m_selected), QColor(kSelectedRgb), Swatch::ThickLine});
        entries.push_back({tr("other layers"), dimmedLayerColour(0), Swatch::DimmedPalette});
    } else {
        entries.push_back({tr("toolpath, layers in turn"), layerColour(0), Swatch::Palette});
    }
    if (m_selected >= 0 && !scene.layers[static_cast<std::size_t>(m_selected)].section.empty()) {
        entries.push_back(
            {tr("blade section at layer %1 (%2 = %3 mm)")
                 .arg(m_selected)
                 .arg(m_alongLetter)
                 .arg(signedNumber(scene.layers[static_cast<std::size_t>(m_selected)].sectionX, 1)),
             QColor(kSectionRgb), Swatch::Line});
    }
    const std::size_t stride = axisStride();
    const QString every = stride > 1 ? tr(", 1 in %1").arg(stride) : QString();
    if (rescheduledAxesVisible() && scene.hasRescheduled()) {
        entries.push_back(
            {tr("re-scheduled tool axes%1").arg(every), QColor(kRescheduledAxisRgb), Swatch::Line});
    }
    if (originalAxesVisible() && !scene.originalAxes.empty()) {
        entries.push_back(
            {tr("original tool axes%1").arg(every), QColor(kOriginalAxisRgb), Swatch::Line});
    }
    if (toolVisible()) {
        entries.push_back({tr("tool: ball R %1 mm and shank").arg(m_vtk->toolRadius, 0, 'g', 4),
                           QColor(kToolRgb), Swatch::Area});
    }
    if (m_vtk->surface.actor->GetVisibility() != 0 && !scene.surface.triangles.empty()) {
        entries.push_back({tr("blade: %1").arg(QString::fromStdString(scene.surfaceName)),
                           QColor(kSurfaceRgb), Swatch::Area});
    }
    return entries;
}

QStringList ToolpathView::legendEntries() const {
    QStringList texts;
    for (const LegendEntry& entry : legend()) {
        texts << entry.text;
    }
    return texts;
}

QImage ToolpathView::renderFrame() {
    syncViewport();
    const QSize size = renderSize();
    const int w = size.width(), h = size.height();
    m_vtk->window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    m_vtk->window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, pixels);
    // VTK's rows start at the bottom.
    QImage frame = QImage(reinterpret_cast<const uchar*>(pixels->GetPointer(0)), w, h, 4 * w,
                          QImage::Format_RGBX8888)
                       .mirrored();
    paintLegend(frame);
    return frame;
}

// The legend band right of the scene: every colour drawn, what it means, the speed colour bar
// and the W axes as the camera sees them. Painted by Qt: cheaper than VTK's annotation actors
// and identical in screenshots.
void ToolpathView::paintLegend(QImage& frame) {
    QPainter painter(&frame);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setFont(font());
    const QRect area = sceneArea();
    const QRect band(area.right() + 1, 0, frame.width() - area.width(), frame.height());
    painter.fillRect(band, QColor(kLegendBackgroundRgb));
    if (!m_vtk->hasData) {
        return;
    }
    const QFontMetrics metrics(font());
    constexpr int kMargin = 10, kSwatch = 24, kGap = 8;
    const QRect inner = band.adjusted(kMargin, kMargin, -kMargin, -kMargin);
    const int textLeft = inner.left() + kSwatch + kGap;
    int y = inner.top();
    for (const LegendEntry& entry : legend()) {
        painter.setPen(QColor(kTextRgb));
        if (entry.swatch == Swatch::ColourBar) {
            y = paintColourBar(painter, entry.text, QRect(inner.left(), y, inner.width(), 0)) +
                kGap;
            continue;
        }
        const QRect text = metrics.boundingRect(QRect(textLeft, y, inner.right() - textLeft, 1000),
                                                Qt::TextWordWrap, entry.text);
        paintSwatch(painter, entry, QRectF(inner.left(), y, kSwatch, metrics.height()));
        painter.setPen(QColor(kTextRgb));
        painter.drawText(text, Qt::TextWordWrap, entry.text);
        y = text.bottom() + kGap;
    }
    paintAxesMarker(painter, QPointF(band.left() + 40.0, frame.height() - 40.0));
}

// The title, the speed colours from 0 to the top of the scale (deg/s) and their range, from the
// top of `row` across its width; returns the bottom.
int ToolpathView::paintColourBar(QPainter& painter, const QString& title, const QRect& row) const {
    const QFontMetrics metrics(painter.font());
    const QRect text = metrics.boundingRect(QRect(row.left(), row.top(), row.width(), 1000),
                                            Qt::TextWordWrap, title);
    painter.drawText(text, Qt::TextWordWrap, title);
    const QRect bar(row.left(), text.bottom() + 4, row.width(), 10);
    QLinearGradient gradient(bar.topLeft(), bar.topRight());
    for (int step = 0; step <= 8; ++step) {
        gradient.setColorAt(step / 8.0, speedColour(step / 8.0));
    }
    painter.fillRect(bar, gradient);
    const int baseline = bar.bottom() + 2 + metrics.ascent();
    painter.drawText(bar.left(), baseline, QStringLiteral("0"));
    const QString top =
        QStringLiteral("\u2265 ") + QString::number(units::radToDeg(m_vtk->speedScale), 'f', 0);
    painter.drawText(bar.right() - metrics.horizontalAdvance(top), baseline, top);
    return baseline + metrics.descent();
}

// X (red), Y (green) and Z (blue) of W from `origin`, turned as the camera sees them.
void ToolpathView::paintAxesMarker(QPainter& painter, QPointF origin) const {
    // Rows of the view matrix are the camera's right, up and backward directions in W.
    vtkMatrix4x4* view = m_vtk->renderer->GetActiveCamera()->GetViewTransformMatrix();
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

} // namespace bladeaxis::ui

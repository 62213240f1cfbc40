#include "ui/profile_plots.h"

#include "core/kinematics/machine_model.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace bladeaxis::ui {
namespace {

struct Series {
    const std::vector<double>* time;
    const std::vector<double>* values;
    QColor colour;
    Qt::PenStyle style;
    double scale; // display unit per internal unit (rad -> deg)
};

void drawPlot(QPainter& painter, QRectF area, const QString& title,
              const std::vector<Series>& series) {
    painter.setPen(QPen(QColor(128, 128, 128)));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(area);
    painter.drawText(area.adjusted(6, 2, 0, 0), Qt::AlignLeft | Qt::AlignTop, title);
    double tMax = 0.0, low = 0.0, high = 0.0;
    for (const Series& one : series) {
        if (one.time->empty() || one.values->empty()) {
            continue;
        }
        tMax = std::max(tMax, one.time->back());
        const auto [minIt, maxIt] = std::minmax_element(one.values->begin(), one.values->end());
        low = std::min(low, *minIt * one.scale);
        high = std::max(high, *maxIt * one.scale);
    }
    if (tMax <= 0.0 || high <= low) {
        return;
    }
    const QRectF plot = area.adjusted(4, 18, -4, -4);
    painter.drawText(area.adjusted(0, 2, -6, 0), Qt::AlignRight | Qt::AlignTop,
                     QStringLiteral("[%1, %2]").arg(low, 0, 'g', 3).arg(high, 0, 'g', 3));
    for (const Series& one : series) {
        const std::size_t count = std::min(one.time->size(), one.values->size());
        QPolygonF line;
        line.reserve(static_cast<qsizetype>(count));
        for (std::size_t i = 0; i < count; ++i) {
            const double x = plot.left() + (*one.time)[i] / tMax * plot.width();
            const double y =
                plot.bottom() - ((*one.values)[i] * one.scale - low) / (high - low) * plot.height();
            line << QPointF(x, y);
        }
        painter.setPen(QPen(one.colour, 1.2, one.style));
        painter.drawPolyline(line);
    }
}

} // namespace

ProfilePlots::ProfilePlots(QWidget* parent) : QWidget(parent) {
    setMinimumSize(320, 300);
    setToolTip(tr("Axis motion against time at the constant feed: original dashed, "
                  "re-scheduled solid"));
}

void ProfilePlots::setProfiles(const analysis::AxisProfile& original,
                               const std::optional<analysis::AxisProfile>& rescheduled) {
    m_original = original;
    m_rescheduled = rescheduled;
    update();
}

void ProfilePlots::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    if (!m_original) {
        painter.drawText(rect(), Qt::AlignCenter, tr("Run a job to see the axis motion"));
        return;
    }
    const auto a = static_cast<std::size_t>(kinematics::AxisId::A);
    constexpr double kDeg = 180.0 / std::numbers::pi;
    const QColor before(140, 140, 140);
    const QColor after(200, 40, 40);
    auto beforeAfter = [&](const std::vector<double> analysis::AxisSeries::*member) {
        std::vector<Series> series{
            {&m_original->time, &(m_original->axes[a].*member), before, Qt::DashLine, kDeg}};
        if (m_rescheduled) {
            series.push_back({&m_rescheduled->time, &(m_rescheduled->axes[a].*member), after,
                              Qt::SolidLine, kDeg});
        }
        return series;
    };
    const double rowHeight = height() / 4.0;
    auto row = [&](int index) {
        return QRectF(4.0, index * rowHeight + 2.0, width() - 8.0, rowHeight - 4.0);
    };
    drawPlot(painter, row(0), tr("A position [deg]"), beforeAfter(&analysis::AxisSeries::position));
    drawPlot(painter, row(1), tr("A velocity [deg/s]"),
             beforeAfter(&analysis::AxisSeries::velocity));
    drawPlot(painter, row(2), tr("A acceleration [deg/s²]"),
             beforeAfter(&analysis::AxisSeries::acceleration));
    const analysis::AxisProfile& shown = m_rescheduled ? *m_rescheduled : *m_original;
    const QColor xyz[3] = {QColor(200, 60, 60), QColor(60, 160, 60), QColor(60, 90, 200)};
    std::vector<Series> linear;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        linear.push_back({&shown.time, &shown.axes[axis].velocity, xyz[axis], Qt::SolidLine, 1.0});
    }
    drawPlot(painter, row(3), tr("X, Y, Z velocity [mm/s] (red, green, blue)"), linear);
}

} // namespace bladeaxis::ui

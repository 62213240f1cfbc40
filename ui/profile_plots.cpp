#include "ui/profile_plots.h"

#include "core/base/units.h"
#include "core/kinematics/machine_model.h"
#include "ui/axis_ticks.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QToolTip>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <limits>

namespace bladeaxis::ui {

namespace {

using kinematics::AxisId;

// Titles with units, in the order of ProfilePlots::Quantity; %1 is the axis's letter.
QString titlePattern(int quantity) {
    switch (quantity) {
    case ProfilePlots::APosition:
        return ProfilePlots::tr("%1 position [deg]");
    case ProfilePlots::AVelocity:
        return ProfilePlots::tr("%1 velocity [deg/s]");
    case ProfilePlots::AAcceleration:
        return ProfilePlots::tr("%1 acceleration [deg/s²]");
    default:
        return ProfilePlots::tr("%1 velocity [mm/s]");
    }
}

// The axis role a quantity shows.
AxisId axisOf(int quantity) {
    switch (quantity) {
    case ProfilePlots::XVelocity:
        return AxisId::X;
    case ProfilePlots::YVelocity:
        return AxisId::Y;
    case ProfilePlots::ZVelocity:
        return AxisId::Z;
    default:
        return AxisId::A;
    }
}

std::vector<double> inDegrees(const std::vector<double>& radians) {
    std::vector<double> degrees(radians.size());
    std::transform(radians.begin(), radians.end(), degrees.begin(), units::radToDeg);
    return degrees;
}

ProfilePlots::Curve curveOf(const QString& method, const analysis::AxisProfile& profile,
                            bool dashed) {
    ProfilePlots::Curve curve;
    curve.method = method;
    curve.dashed = dashed;
    curve.time = profile.times();
    const analysis::AxisSeries& a = profile.axis(AxisId::A);
    curve.values[ProfilePlots::APosition] = inDegrees(profile.positions(AxisId::A));
    const std::size_t n = curve.time.size();
    curve.values[ProfilePlots::AVelocity] = inDegrees(a.velocities(n));
    curve.values[ProfilePlots::AAcceleration] = inDegrees(a.accelerations(n));
    curve.values[ProfilePlots::XVelocity] = profile.axis(AxisId::X).velocities(n);
    curve.values[ProfilePlots::YVelocity] = profile.axis(AxisId::Y).velocities(n);
    curve.values[ProfilePlots::ZVelocity] = profile.axis(AxisId::Z).velocities(n);
    return curve;
}

bool isDark(const QPalette& palette) {
    return palette.color(QPalette::Base).lightness() < 128;
}

// A value between a and b, 0 giving a.
QColor blend(const QColor& a, const QColor& b, double t) {
    auto mix = [t](int x, int y) { return static_cast<int>(std::lround(x + (y - x) * t)); };
    return QColor(mix(a.red(), b.red()), mix(a.green(), b.green()), mix(a.blue(), b.blue()));
}

QColor curveColour(const ProfilePlots::Curve& curve, const QPalette& palette) {
    if (curve.method == QLatin1String("original")) { // neutral: the text colour, toned down
        return blend(palette.color(QPalette::Text), palette.color(QPalette::Base), 0.35);
    }
    return ProfilePlots::methodColour(curve.method, isDark(palette));
}

struct Range {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    bool valid() const { return low <= high; }
    void include(double value) {
        if (std::isfinite(value)) {
            low = std::min(low, value);
            high = std::max(high, value);
        }
    }
};

// At most two points per pixel column (the column's extremes, in path order), so that peaks
// survive and a million-sample path still draws quickly.
QPolygonF decimatedLine(const std::vector<double>& time, const std::vector<double>& values,
                        const QRectF& plot, const Range& xRange, const Range& yRange) {
    const std::size_t count = std::min(time.size(), values.size());
    auto toX = [&](double t) {
        return plot.left() + (t - xRange.low) / (xRange.high - xRange.low) * plot.width();
    };
    auto toY = [&](double v) {
        return plot.bottom() - (v - yRange.low) / (yRange.high - yRange.low) * plot.height();
    };
    QPolygonF line;
    line.reserve(static_cast<qsizetype>(
        std::min(count, 2 * static_cast<std::size_t>(std::max(plot.width(), 0.0)) + 4)));
    std::size_t i = 0;
    while (i < count) {
        const double column = std::floor(toX(time[i]));
        std::size_t lowest = i, highest = i, end = i;
        while (end < count && std::floor(toX(time[end])) == column) {
            lowest = values[end] < values[lowest] ? end : lowest;
            highest = values[end] > values[highest] ? end : highest;
            ++end;
        }
        for (std::size_t index : {std::min(lowest, highest), std::max(lowest, highest)}) {
            line << QPointF(toX(time[index]), toY(values[index]));
        }
        i = end;
    }
    return line;
}

// The data rectangle of a plot cell: room for the title above, tick labels left and below.
QRectF plotRect(const QRectF& area, const QFontMetricsF& metrics) {
    return area.adjusted(metrics.horizontalAdvance(QStringLiteral("-000.0k")) + 8,
                         metrics.height() + 4, -8, -(metrics.height() + 6));
}

// The common time axis: the longest visible method (each is drawn over its own duration).
double visibleDuration(const std::vector<ProfilePlots::Curve>& curves) {
    double duration = 0.0;
    for (const ProfilePlots::Curve& curve : curves) {
        if (curve.visible && !curve.time.empty()) {
            duration = std::max(duration, curve.time.back());
        }
    }
    return duration;
}

// What a plot draws beyond its curves.
struct PlotOptions {
    std::array<QString, ProfilePlots::kQuantityCount> titles; // with units
    QString logTitle;                              // the A acceleration's title on the log axis
    std::optional<double> cursor;                  // s: the mouse readout's time line
    std::optional<double> marked;                  // s: the selected point's time line
    bool logAcceleration = false;                  // A acceleration as |a| on a log axis
    std::optional<std::pair<double, double>> span; // s: the selected layer's time span
    QString spanLabel;
    std::array<std::optional<double>, ProfilePlots::kQuantityCount> limits; // display units
    double logFloor = 1.0;                                                  // deg/s²
    QString exported;                                // the method Export writes: drawn thicker
    std::optional<std::pair<double, double>> window; // s: the zoomed time span, none: all
};

// |a| below the floor (deg/s²) is drawn at it on the log axis: quiet stretches stay on the plot
// instead of falling to minus infinity.
std::vector<double> logMagnitudes(const std::vector<double>& values, double floor) {
    std::vector<double> logs(values.size());
    std::transform(values.begin(), values.end(), logs.begin(),
                   [floor](double v) { return std::log10(std::max(std::abs(v), floor)); });
    return logs;
}

// The largest value of each pixel column, in path order: the log plot's upper envelope. Where
// the acceleration crosses zero, |a| dips to the floor for one sample; drawn sample by sample
// (or column extremes) a smooth schedule becomes a comb of spikes down to the floor, which says
// nothing about the motion. The envelope shows the magnitude the axis reaches in each column.
QPolygonF envelopeLine(const std::vector<double>& time, const std::vector<double>& values,
                       const QRectF& plot, std::pair<double, double> window, double low,
                       double high) {
    const auto columnOf = [&](double t) {
        return std::floor((t - window.first) / (window.second - window.first) * plot.width());
    };
    const std::size_t count = std::min(time.size(), values.size());
    QPolygonF line;
    std::size_t i = 0;
    while (i < count) {
        const double column = columnOf(time[i]);
        double largest = values[i];
        std::size_t end = i;
        while (end < count && columnOf(time[end]) == column) {
            largest = std::max(largest, values[end]);
            ++end;
        }
        line << QPointF(plot.left() + (column + 0.5), largest);
        i = end;
    }
    // Each column shows the largest value within kEnvelopeColumns of it: the zero crossings of a
    // smooth acceleration (a few columns wide) are filled, no peak is lowered.
    constexpr qsizetype kEnvelopeColumns = 3;
    QPolygonF filled(line);
    for (qsizetype k = 0; k < line.size(); ++k) {
        double largest = line[k].y();
        for (qsizetype m = std::max<qsizetype>(0, k - kEnvelopeColumns);
             m <= std::min(line.size() - 1, k + kEnvelopeColumns); ++m) {
            if (std::abs(line[m].x() - line[k].x()) <= kEnvelopeColumns) {
                largest = std::max(largest, line[m].y());
            }
        }
        filled[k].setY(plot.bottom() - (largest - low) / (high - low) * plot.height());
    }
    return filled;
}

QString decadeLabel(double exponent) {
    static const char* const kNames[] = {"1",    "10", "100", "1k",  "10k",
                                         "100k", "1M", "10M", "100M"};
    const auto k = static_cast<int>(std::lround(exponent));
    return k >= 0 && k < 9 ? QString::fromLatin1(kNames[k]) : QStringLiteral("1e%1").arg(k);
}

// One plot: frame, grid with tick labels on both axes, the visible curves.
class PlotPainter {
  public:
    PlotPainter(QPainter& painter, const QPalette& palette) : m_p(painter), m_palette(palette) {}

    void draw(const QRectF& area, int quantity, const std::vector<ProfilePlots::Curve>& curves,
              const PlotOptions& options) {
        const QFontMetricsF metrics(m_p.font());
        const bool log = options.logAcceleration && quantity == ProfilePlots::AAcceleration;
        const Range xRange = options.window ? Range{options.window->first, options.window->second}
                                            : Range{0.0, visibleDuration(curves)};
        std::vector<std::vector<double>> shown; // per curve, in plot units (log10 |a| or as is)
        Range yRange;
        for (const ProfilePlots::Curve& curve : curves) {
            shown.push_back(log && curve.visible
                                ? logMagnitudes(curve.values[quantity], options.logFloor)
                                : std::vector<double>{});
            if (curve.visible) {
                for (double value : log ? shown.back() : curve.values[quantity]) {
                    yRange.include(value);
                }
            }
        }
        const std::optional<double> limit = options.limits[quantity];
        if (limit && yRange.valid()) { // the limit is part of what the plot shows
            yRange.include(log ? std::log10(*limit) : *limit);
            if (!log) {
                yRange.include(-*limit);
            }
        }
        const QRectF plot = plotRect(area, metrics);
        m_p.setPen(m_palette.color(QPalette::Text));
        const QString title = log ? options.logTitle : options.titles[quantity];
        m_p.drawText(area.adjusted(plot.left() - area.left(), 0, 0, 0),
                     Qt::AlignLeft | Qt::AlignTop, title);
        if (!(xRange.high > xRange.low) || !yRange.valid() || plot.width() < 10 ||
            plot.height() < 10) {
            m_p.drawRect(plot);
            return;
        }
        if (log) {
            yRange.low = std::floor(yRange.low);
            yRange.high = std::max(std::ceil(yRange.high), yRange.low + 1.0);
            drawDecades(plot, yRange, metrics);
        } else {
            padRange(yRange);
            drawYTicks(plot, yRange, metrics);
        }
        drawXTicks(plot, xRange, metrics);
        if (options.span) {
            drawSpan(plot, xRange, *options.span, options.spanLabel, metrics);
        }
        m_p.save();
        m_p.setClipRect(plot);
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const ProfilePlots::Curve& curve = curves[i];
            if (curve.visible) {
                const bool exported = curve.method == options.exported;
                m_p.setPen(QPen(curveColour(curve, m_palette),
                                exported ? 2.4 : (curve.dashed ? 1.2 : 1.5),
                                curve.dashed ? Qt::DashLine : Qt::SolidLine));
                m_p.drawPolyline(
                    log ? envelopeLine(curve.time, shown[i], plot, {xRange.low, xRange.high},
                                       yRange.low, yRange.high)
                        : decimatedLine(curve.time, curve.values[quantity], plot, xRange, yRange));
            }
        }
        if (limit) {
            drawLimit(plot, yRange, *limit, log, metrics);
        }
        m_p.restore();
        m_p.setPen(m_palette.color(QPalette::Text));
        m_p.setBrush(Qt::NoBrush);
        m_p.drawRect(plot);
        drawTimeLine(plot, xRange, options.marked,
                     QPen(m_palette.color(QPalette::Highlight), 1.5, Qt::SolidLine));
        drawTimeLine(plot, xRange, options.cursor,
                     QPen(m_palette.color(QPalette::Text), 1.0, Qt::DotLine));
    }

  private:
    void drawTimeLine(const QRectF& plot, const Range& xRange, std::optional<double> time,
                      const QPen& pen) {
        if (!time || *time < xRange.low || *time > xRange.high) {
            return;
        }
        const double x =
            plot.left() + (*time - xRange.low) / (xRange.high - xRange.low) * plot.width();
        m_p.setPen(pen);
        m_p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    }

    // The machine's limit: a red dashed line at +limit and -limit (at the limit alone on the
    // log axis of |a|), labelled at its right end.
    void drawLimit(const QRectF& plot, const Range& range, double limit, bool log,
                   const QFontMetricsF& metrics) {
        const QColor red(200, 40, 40);
        m_p.setPen(QPen(red, 1.2, Qt::DashDotLine));
        const QString label = ProfilePlots::tr("limit %1").arg(QLocale().toString(limit, 'g', 4));
        for (double value :
             log ? std::vector<double>{std::log10(limit)} : std::vector<double>{limit, -limit}) {
            const double y =
                plot.bottom() - (value - range.low) / (range.high - range.low) * plot.height();
            m_p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            const double width = metrics.horizontalAdvance(label) + 4.0;
            // Beside the line, on the side away from zero unless the plot's edge is there.
            double top = value >= 0.0 ? y - metrics.height() - 1.0 : y + 1.0;
            if (top < plot.top() || top + metrics.height() > plot.bottom()) {
                top = value >= 0.0 ? y + 1.0 : y - metrics.height() - 1.0;
            }
            m_p.drawText(QRectF(plot.right() - width, top, width, metrics.height()),
                         Qt::AlignRight | Qt::AlignVCenter, label);
        }
    }

    static void padRange(Range& range) {
        const double span = range.high - range.low;
        const double pad = span > 0.0 ? 0.05 * span : std::max(1.0, std::abs(range.high) * 0.1);
        range.low -= pad;
        range.high += pad;
    }

    QPen gridPen() const {
        return QPen(blend(m_palette.color(QPalette::Base), m_palette.color(QPalette::Text), 0.15),
                    1.0);
    }

    void drawYTicks(const QRectF& plot, const Range& range, const QFontMetricsF& metrics) {
        const int maxTicks =
            std::max(2, static_cast<int>(plot.height() / (1.6 * metrics.height())));
        const double step = niceStep(range.high - range.low, maxTicks);
        for (double value = std::ceil(range.low / step) * step; value <= range.high;
             value += step) {
            const double y =
                plot.bottom() - (value - range.low) / (range.high - range.low) * plot.height();
            m_p.setPen(gridPen());
            m_p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            m_p.setPen(m_palette.color(QPalette::Text));
            const QRectF label(plot.left() - 200.0 - 4.0, y - metrics.height() / 2, 200.0,
                               metrics.height());
            m_p.drawText(label, Qt::AlignRight | Qt::AlignVCenter, tickLabel(value, step));
        }
    }

    // Whole decades of |a| (1, 10, 100, 1k ...), each a grid line.
    void drawDecades(const QRectF& plot, const Range& range, const QFontMetricsF& metrics) {
        const double decades = range.high - range.low;
        const int every =
            std::max(1, static_cast<int>(std::ceil(
                            decades / std::max(1.0, plot.height() / (1.6 * metrics.height())))));
        for (double exponent = range.low; exponent <= range.high + 1e-9; exponent += every) {
            const double y = plot.bottom() - (exponent - range.low) / decades * plot.height();
            m_p.setPen(gridPen());
            m_p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
            m_p.setPen(m_palette.color(QPalette::Text));
            m_p.drawText(
                QRectF(plot.left() - 204.0, y - metrics.height() / 2, 200.0, metrics.height()),
                Qt::AlignRight | Qt::AlignVCenter, decadeLabel(exponent));
        }
    }

    // The selected layer's time span: a tinted band behind the curves, named at its top.
    void drawSpan(const QRectF& plot, const Range& xRange, std::pair<double, double> span,
                  const QString& label, const QFontMetricsF& metrics) {
        const double from = std::clamp(span.first, xRange.low, xRange.high);
        const double to = std::clamp(span.second, xRange.low, xRange.high);
        if (!(to > from)) {
            return;
        }
        const double x0 =
            plot.left() + (from - xRange.low) / (xRange.high - xRange.low) * plot.width();
        const double x1 =
            plot.left() + (to - xRange.low) / (xRange.high - xRange.low) * plot.width();
        QColor tint = m_palette.color(QPalette::Highlight);
        tint.setAlpha(45);
        m_p.fillRect(QRectF(x0, plot.top(), x1 - x0, plot.height()), tint);
        if (x1 - x0 > metrics.horizontalAdvance(label) + 4.0) {
            m_p.setPen(m_palette.color(QPalette::Text));
            m_p.drawText(QRectF(x0, plot.top() + 1.0, x1 - x0, metrics.height()),
                         Qt::AlignHCenter | Qt::AlignTop, label);
        }
    }

    void drawXTicks(const QRectF& plot, const Range& range, const QFontMetricsF& metrics) {
        const double labelWidth = metrics.horizontalAdvance(QStringLiteral("0000.0")) * 1.5;
        const int maxTicks = std::max(2, static_cast<int>(plot.width() / labelWidth));
        const double step = niceStep(range.high - range.low, maxTicks);
        const QString unit = ProfilePlots::tr("t [s]");
        const double unitLeft = plot.right() - metrics.horizontalAdvance(unit) - 2.0;
        for (double value = std::ceil(range.low / step) * step; value <= range.high;
             value += step) {
            const double x =
                plot.left() + (value - range.low) / (range.high - range.low) * plot.width();
            m_p.setPen(gridPen());
            m_p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
            const QString text = tickLabel(value, step);
            if (x + metrics.horizontalAdvance(text) / 2 + 4.0 < unitLeft) { // leaves the unit clear
                m_p.setPen(m_palette.color(QPalette::Text));
                m_p.drawText(
                    QRectF(x - labelWidth / 2, plot.bottom() + 2, labelWidth, metrics.height()),
                    Qt::AlignHCenter | Qt::AlignTop, text);
            }
        }
        m_p.setPen(m_palette.color(QPalette::Text));
        m_p.drawText(QRectF(unitLeft, plot.bottom() + 2, plot.right() - unitLeft, metrics.height()),
                     Qt::AlignRight | Qt::AlignTop, unit);
    }

    QPainter& m_p;
    const QPalette& m_palette;
};

QPixmap legendIcon(const QColor& colour, bool dashed) {
    QPixmap icon(24, 12);
    icon.fill(Qt::transparent);
    QPainter painter(&icon);
    painter.setPen(QPen(colour, 2.0, dashed ? Qt::DashLine : Qt::SolidLine));
    painter.drawLine(QPointF(1, 6), QPointF(23, 6));
    return icon;
}

} // namespace

namespace detail {

// The plots themselves, below the legend. Hovering a plot marks that time in every plot and
// shows each visible method's value there.
class PlotCanvas final : public QWidget {
  public:
    PlotCanvas(ProfilePlots& owner, QWidget* parent) : QWidget(parent), m_owner(owner) {
        setMinimumSize(320, 260);
        setMouseTracking(true);
    }

  protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.fillRect(rect(), palette().base());
        if (m_owner.curves().empty()) {
            painter.setPen(palette().color(QPalette::Text));
            painter.drawText(rect(), Qt::AlignCenter,
                             ProfilePlots::tr("Run a job to see the axis motion"));
            return;
        }
        PlotPainter plotter(painter, palette());
        PlotOptions options;
        options.cursor = m_cursor;
        options.marked = m_owner.markedTime();
        options.logAcceleration = m_owner.accelerationLogScale();
        options.logFloor = m_owner.accelerationLogFloor();
        options.exported = m_owner.exportedMethod();
        for (int quantity = 0; quantity < ProfilePlots::kQuantityCount; ++quantity) {
            const auto which = static_cast<ProfilePlots::Quantity>(quantity);
            options.limits[quantity] = m_owner.limitOf(which);
            options.titles[quantity] = m_owner.quantityTitle(which);
        }
        options.window = m_owner.timeWindow();
        options.span = m_owner.highlightedSpan();
        options.spanLabel = m_owner.highlightedSpanLabel();
        options.logTitle = m_owner.logAccelerationTitle();
        for (int quantity = 0; quantity < ProfilePlots::kQuantityCount; ++quantity) {
            plotter.draw(cellArea(quantity), quantity, m_owner.curves(), options);
        }
    }

    void mouseMoveEvent(QMouseEvent* event) override {
        const QPointF position = event->position();
        if (m_dragFrom && (event->buttons() & Qt::LeftButton)) {
            if (const auto at = plotAt(position)) {
                m_owner.panTime(-(position.x() - *m_dragFrom) / at->plot.width() *
                                (at->span.second - at->span.first));
                m_dragFrom = position.x();
            }
        }
        if (const auto at = plotAt(position)) {
            m_cursor = at->timeAt(position.x());
            QToolTip::showText(
                event->globalPosition().toPoint(),
                m_owner.valuesAt(*m_cursor, static_cast<ProfilePlots::Quantity>(at->quantity)),
                this);
            update();
            return;
        }
        clearCursor();
    }

    void leaveEvent(QEvent*) override { clearCursor(); }

  private:
    // Two columns (A on the left, X/Y/Z on the right) when there is room, else one.
    QRectF cellArea(int quantity) const {
        const int columns = width() >= 640 ? 2 : 1;
        const int rows = ProfilePlots::kQuantityCount / columns;
        const double cellWidth = width() / static_cast<double>(columns);
        const double cellHeight = height() / static_cast<double>(rows);
        const int column = quantity / rows, row = quantity % rows;
        return QRectF(column * cellWidth + 2, row * cellHeight + 2, cellWidth - 4, cellHeight - 4);
    }

    void clearCursor() {
        if (m_cursor) {
            m_cursor.reset();
            QToolTip::hideText();
            update();
        }
    }

    // A plot under the mouse: its rectangle, the time span it shows and its quantity.
    struct PlotHit {
        QRectF plot;
        std::pair<double, double> span; // s
        int quantity = 0;
        // The time at pixel column `x` of the plot.
        double timeAt(double x) const {
            return span.first + (x - plot.left()) / plot.width() * (span.second - span.first);
        }
    };

    // The plot under `position`, none outside every plot.
    std::optional<PlotHit> plotAt(QPointF position) const {
        const double duration = visibleDuration(m_owner.curves());
        const std::pair<double, double> span =
            m_owner.timeWindow().value_or(std::pair{0.0, duration});
        for (int quantity = 0; quantity < ProfilePlots::kQuantityCount; ++quantity) {
            const QRectF plot = plotRect(cellArea(quantity), QFontMetricsF(font()));
            if (span.second > span.first && plot.contains(position)) {
                return PlotHit{plot, span, quantity};
            }
        }
        return std::nullopt;
    }

    // The wheel zooms the time axis about the time under the mouse.
    void wheelEvent(QWheelEvent* event) override {
        const auto at = plotAt(event->position());
        if (!at || event->angleDelta().y() == 0) {
            event->ignore();
            return;
        }
        m_owner.zoomTime(event->angleDelta().y() > 0 ? 0.8 : 1.25,
                         at->timeAt(event->position().x()));
        event->accept();
    }

    void mousePressEvent(QMouseEvent* event) override {
        if (event->button() == Qt::LeftButton && plotAt(event->position())) {
            m_dragFrom = event->position().x();
            m_pressedAt = event->position();
        }
    }

    // A release where the press was (a click, not a pan) says the time under it.
    void mouseReleaseEvent(QMouseEvent* event) override {
        m_dragFrom.reset();
        const bool click = event->button() == Qt::LeftButton && m_pressedAt &&
                           (event->position() - *m_pressedAt).manhattanLength() <= kClickSlopPx;
        m_pressedAt.reset();
        if (const auto at = click ? plotAt(event->position()) : std::nullopt) {
            emit m_owner.timeClicked(at->timeAt(event->position().x()));
        }
    }

    static constexpr double kClickSlopPx = 3.0; // a press and release closer than this: a click

    ProfilePlots& m_owner;
    std::optional<double> m_cursor;   // s
    std::optional<double> m_dragFrom; // px: a left drag pans the time axis
    std::optional<QPointF> m_pressedAt;
};

} // namespace detail

ProfilePlots::ProfilePlots(QWidget* parent) : QWidget(parent) {
    setMinimumSize(320, 300);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    // The legend scrolls sideways rather than widening the plots in a narrow window.
    m_legendArea = new QScrollArea(this);
    m_legendArea->setFrameShape(QFrame::NoFrame);
    m_legendArea->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_legendArea->setWidgetResizable(true);
    m_legendArea->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    auto* legendRow = new QWidget(m_legendArea);
    legendRow->setToolTip(tr("Axis motion against time at the programmed feed, each method on its "
                             "own time axis; the original dashed, the exported program bold. Tick "
                             "another method to compare it, untick one to hide it and rescale; "
                             "hover a plot to read every method's value. Red dashed lines: the "
                             "machine's limits."));
    m_legend = new QHBoxLayout(legendRow);
    m_legend->setContentsMargins(6, 2, 6, 0);
    m_legendArea->setWidget(legendRow);
    m_canvas = new detail::PlotCanvas(*this, this);
    m_logBox = new QCheckBox(this); // its text names the table's letter (setAxisLetters)
    m_logBox->setObjectName(QStringLiteral("accelerationLogScale"));
    m_logBox->setChecked(m_logAcceleration);
    connect(m_logBox, &QCheckBox::toggled, this, &ProfilePlots::setAccelerationLogScale);
    auto* fit = new QPushButton(tr("Fit"), this);
    fit->setObjectName(QStringLiteral("fitPlots"));
    fit->setToolTip(tr("Show the whole time axis again (the wheel zooms it, a drag pans it)"));
    connect(fit, &QPushButton::clicked, this, &ProfilePlots::fitTime);
    auto* top = new QHBoxLayout;
    top->setContentsMargins(0, 0, 6, 0);
    top->addWidget(m_legendArea, 1);
    top->addWidget(m_logBox);
    top->addWidget(fit);
    layout->addLayout(top);
    layout->addWidget(m_canvas, 1);
    setAutoFillBackground(true);
    setBackgroundRole(QPalette::Base);
    setAxisLetters(m_letters);
}

void ProfilePlots::setProfiles(const analysis::AxisProfile& original,
                               const std::optional<analysis::AxisProfile>& rescheduled) {
    std::vector<Curve> curves{curveOf(QStringLiteral("original"), original, true)};
    m_exported = QStringLiteral("re-scheduled");
    if (rescheduled) {
        curves.push_back(curveOf(QStringLiteral("re-scheduled"), *rescheduled, false));
    }
    setCurves(std::move(curves));
}

void ProfilePlots::setComparison(const compare::Comparison& comparison, const QString& exported) {
    m_exported = exported;
    std::vector<Curve> curves;
    for (const compare::MethodResult& method : comparison.methods) {
        const QString name = QString::fromStdString(method.method);
        curves.push_back(curveOf(name, method.profile, method.method == "original"));
    }
    setCurves(std::move(curves));
}

void ProfilePlots::addProfile(const QString& method, const analysis::AxisProfile& profile) {
    std::vector<Curve> curves;
    for (const Curve& curve : m_curves) {
        if (curve.method != method) {
            curves.push_back(curve);
        }
    }
    curves.push_back(curveOf(method, profile, method == QLatin1String("original")));
    setCurves(std::move(curves));
}

void ProfilePlots::setTimeWindow(std::optional<std::pair<double, double>> seconds) {
    const double duration = visibleDuration(m_curves);
    if (seconds && duration > 0.0) {
        // Within the pass, at least a millisecond wide; the whole pass is no zoom at all.
        const double width = std::clamp(seconds->second - seconds->first, 1e-3, duration);
        const double from = std::clamp(seconds->first, 0.0, duration - width);
        seconds = std::pair{from, from + width};
        if (width >= duration) {
            seconds.reset();
        }
    } else {
        seconds.reset();
    }
    m_timeWindow = seconds;
    m_canvas->update();
}

void ProfilePlots::zoomTime(double factor, double aroundSeconds) {
    const auto [from, to] = m_timeWindow.value_or(std::pair{0.0, visibleDuration(m_curves)});
    setTimeWindow(std::pair{aroundSeconds - (aroundSeconds - from) * factor,
                            aroundSeconds + (to - aroundSeconds) * factor});
}

void ProfilePlots::panTime(double seconds) {
    if (m_timeWindow) {
        setTimeWindow(std::pair{m_timeWindow->first + seconds, m_timeWindow->second + seconds});
    }
}

void ProfilePlots::fitTime() {
    setTimeWindow(std::nullopt);
}

void ProfilePlots::setExportedMethod(const QString& method) {
    m_exported = method;
    setCurves(std::move(m_curves)); // the default pair follows the exported method
}

void ProfilePlots::setMachineLimits(const kinematics::MachineModel& machine) {
    const auto positive = [](double limit) {
        return std::isfinite(limit) && limit > 0.0 ? std::optional(limit) : std::nullopt;
    };
    const auto degrees = [&](double limit) {
        const auto value = positive(limit);
        return value ? std::optional(units::radToDeg(*value)) : std::nullopt;
    };
    m_limits = {};
    m_limits[AVelocity] = degrees(machine.limit(AxisId::A).velocity);
    m_limits[AAcceleration] = degrees(machine.limit(AxisId::A).acceleration);
    m_limits[XVelocity] = positive(machine.limit(AxisId::X).velocity);
    m_limits[YVelocity] = positive(machine.limit(AxisId::Y).velocity);
    m_limits[ZVelocity] = positive(machine.limit(AxisId::Z).velocity);
    m_canvas->update();
}

double ProfilePlots::accelerationLogFloor() const {
    double peak = 0.0;
    for (const Curve& curve : m_curves) {
        if (curve.visible) {
            for (double value : curve.values[AAcceleration]) {
                peak = std::max(peak, std::abs(value));
            }
        }
    }
    constexpr double kDecadesShown = 4.0;
    return std::max(1.0, peak * std::pow(10.0, -kDecadesShown));
}

std::vector<double> ProfilePlots::logAccelerationEnvelope(const QString& method,
                                                          int columns) const {
    std::vector<double> envelope;
    const double duration = visibleDuration(m_curves);
    for (const Curve& curve : m_curves) {
        if (curve.method != method || !(duration > 0.0) || columns <= 0) {
            continue;
        }
        const std::vector<double> logs =
            logMagnitudes(curve.values[AAcceleration], accelerationLogFloor());
        const QPolygonF line =
            envelopeLine(curve.time, logs, QRectF(0, 0, columns, 1.0), {0.0, duration}, 0.0, 1.0);
        for (const QPointF& point : line) {
            envelope.push_back(1.0 - point.y()); // back from the unit rectangle's y
        }
    }
    return envelope;
}

void ProfilePlots::setAxisLetters(const std::array<char, 5>& letters) {
    m_letters = letters;
    const QChar table = QLatin1Char(letters[static_cast<std::size_t>(AxisId::A)]);
    m_logBox->setText(tr("log |%1 acc.|").arg(table));
    m_logBox->setToolTip(tr("%1 acceleration as its magnitude on a logarithmic axis, so the "
                            "original's spikes and the new schedule are both readable")
                             .arg(table));
    m_canvas->update();
}

QString ProfilePlots::quantityTitle(Quantity quantity) const {
    const char letter = m_letters[static_cast<std::size_t>(axisOf(quantity))];
    return titlePattern(quantity).arg(QLatin1Char(letter));
}

QString ProfilePlots::logAccelerationTitle() const {
    return tr("|%1 acceleration| [deg/s²], log scale")
        .arg(QLatin1Char(m_letters[static_cast<std::size_t>(AxisId::A)]));
}

void ProfilePlots::clear() {
    setCurves({});
}

void ProfilePlots::setCurves(std::vector<Curve> curves) {
    for (Curve& curve : curves) {
        const auto chosen = std::find_if(m_chosen.begin(), m_chosen.end(),
                                         [&](const auto& c) { return c.first == curve.method; });
        curve.visible = chosen != m_chosen.end() ? chosen->second
                                                 : curve.method == QLatin1String("original") ||
                                                       curve.method == m_exported;
    }
    m_curves = std::move(curves);
    rebuildLegend();
    setTimeWindow(m_timeWindow); // kept across results, within the new pass
    m_canvas->update();
}

void ProfilePlots::setAccelerationLogScale(bool logScale) {
    if (m_logAcceleration != logScale) {
        m_logAcceleration = logScale;
        const QSignalBlocker blocker(m_logBox);
        m_logBox->setChecked(logScale);
        m_canvas->update();
    }
}

void ProfilePlots::setHighlightedSpan(std::optional<std::pair<double, double>> seconds,
                                      const QString& label) {
    m_span = seconds;
    m_spanLabel = label;
    m_canvas->update();
}

void ProfilePlots::setMarkedTime(std::optional<double> seconds) {
    m_marked = seconds;
    m_canvas->update();
}

QStringList ProfilePlots::methods() const {
    QStringList names;
    for (const Curve& curve : m_curves) {
        names << curve.method;
    }
    return names;
}

bool ProfilePlots::isMethodVisible(const QString& method) const {
    for (const Curve& curve : m_curves) {
        if (curve.method == method) {
            return curve.visible;
        }
    }
    return false;
}

void ProfilePlots::setMethodVisible(const QString& method, bool visible) {
    std::erase_if(m_chosen, [&](const auto& chosen) { return chosen.first == method; });
    m_chosen.emplace_back(method, visible);
    bool changed = false;
    for (std::size_t i = 0; i < m_curves.size(); ++i) {
        if (m_curves[i].method == method && m_curves[i].visible != visible) {
            m_curves[i].visible = visible;
            const QSignalBlocker blocker(m_boxes[i]);
            m_boxes[i]->setChecked(visible);
            changed = true;
        }
    }
    if (changed) {
        m_canvas->update();
        emit methodVisibilityChanged(method, visible);
    }
}

QString ProfilePlots::valuesAt(double time, Quantity quantity) const {
    static const char* const kUnits[kQuantityCount] = {"deg",  "deg/s", "deg/s²",
                                                       "mm/s", "mm/s",  "mm/s"};
    QStringList lines{tr("%1 at t = %2 s").arg(quantityTitle(quantity)).arg(time, 0, 'f', 3)};
    for (const Curve& curve : m_curves) {
        if (!curve.visible || curve.time.empty()) {
            continue;
        }
        const std::vector<double>& values = curve.values[quantity];
        if (values.size() != curve.time.size()) {
            continue;
        }
        if (time > curve.time.back()) {
            lines << tr("%1: finished at %2 s").arg(curve.method).arg(curve.time.back(), 0, 'f', 2);
            continue;
        }
        // Linear between the two samples around `time`.
        const auto above = std::lower_bound(curve.time.begin(), curve.time.end(), time);
        const auto i = static_cast<std::size_t>(above - curve.time.begin());
        double value = values[i];
        if (i > 0 && curve.time[i] > curve.time[i - 1]) {
            const double f = (time - curve.time[i - 1]) / (curve.time[i] - curve.time[i - 1]);
            value = values[i - 1] + f * (values[i] - values[i - 1]);
        }
        lines << QStringLiteral("%1: %2 %3")
                     .arg(curve.method)
                     .arg(value, 0, 'g', 5)
                     .arg(QString::fromUtf8(kUnits[quantity]));
    }
    return lines.join(QLatin1Char('\n'));
}

QColor ProfilePlots::methodColour(const QString& method, bool darkBackground) {
    // Okabe-Ito colours (distinct for colour-blind readers); lighter on a dark background.
    struct Entry {
        const char* method;
        QColor light, dark;
    };
    static const Entry kColours[] = {
        {"original", QColor(110, 110, 110), QColor(170, 170, 170)},
        {"quaternion", QColor(0xE6, 0x9F, 0x00), QColor(0xF0, 0xB8, 0x40)},
        {"stheta-faithful", QColor(0x00, 0x72, 0xB2), QColor(0x56, 0xB4, 0xE9)},
        {"stheta-best", QColor(0xD5, 0x5E, 0x00), QColor(0xFF, 0x80, 0x40)},
        {"re-scheduled", QColor(0xD5, 0x5E, 0x00), QColor(0xFF, 0x80, 0x40)},
        {"optimal-qp", QColor(0x00, 0x9E, 0x73), QColor(0x30, 0xD0, 0xA0)},
        {"optimal-lp", QColor(0xCC, 0x79, 0xA7), QColor(0xE8, 0xA0, 0xC8)},
    };
    for (const Entry& entry : kColours) {
        if (method == QLatin1String(entry.method)) {
            return darkBackground ? entry.dark : entry.light;
        }
    }
    const QColor other(0x80, 0x40, 0xC0); // a method added later: still distinct from the above
    return darkBackground ? other.lighter(150) : other;
}

void ProfilePlots::changeEvent(QEvent* event) {
    if (event->type() == QEvent::PaletteChange) {
        refreshLegendIcons();
    }
    QWidget::changeEvent(event);
}

void ProfilePlots::rebuildLegend() {
    for (QCheckBox* box : m_boxes) {
        m_legend->removeWidget(box);
        delete box;
    }
    m_boxes.clear();
    while (QLayoutItem* item = m_legend->takeAt(0)) { // the stretch
        delete item;
    }
    for (const Curve& curve : m_curves) {
        auto* box = new QCheckBox(curve.method, m_legend->parentWidget());
        box->setChecked(curve.visible);
        box->setObjectName(QStringLiteral("legend_") + curve.method);
        box->setToolTip(tr("Show or hide %1 in every plot").arg(curve.method));
        if (curve.method == m_exported) { // what Export writes, marked and drawn thicker
            QFont bold = box->font();
            bold.setBold(true);
            box->setFont(bold);
            box->setText(tr("%1 (exported)").arg(curve.method));
            box->setToolTip(tr("%1: the program Export writes; show or hide it in every plot")
                                .arg(curve.method));
        }
        const QString method = curve.method;
        connect(box, &QCheckBox::toggled, this,
                [this, method](bool visible) { setMethodVisible(method, visible); });
        m_legend->addWidget(box);
        m_boxes.push_back(box);
    }
    m_legend->addStretch(1);
    refreshLegendIcons();
    // Room for the row and, when it is wider than the window, the scroll bar under it.
    m_legendArea->setFixedHeight(m_legend->parentWidget()->sizeHint().height() +
                                 m_legendArea->horizontalScrollBar()->sizeHint().height());
}

void ProfilePlots::refreshLegendIcons() {
    for (std::size_t i = 0; i < m_boxes.size(); ++i) {
        m_boxes[i]->setIcon(legendIcon(curveColour(m_curves[i], palette()), m_curves[i].dashed));
    }
}

} // namespace bladeaxis::ui

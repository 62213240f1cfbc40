#include "core/report/svg_plot.h"

#include "core/base/number_io.h"
#include "core/report/markup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bladeaxis::report {

namespace {

constexpr std::array<const char*, 8> kPalette{"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                              "#9467bd", "#8c564b", "#e377c2", "#17becf"};
constexpr double kLeft = 70.0, kRight = 16.0, kTop = 30.0, kBottom = 44.0; // margins, px

struct Range {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    void add(double value) {
        if (std::isfinite(value)) {
            low = std::min(low, value);
            high = std::max(high, value);
        }
    }
    void addAll(const std::vector<double>& values) {
        for (double value : values) {
            add(value);
        }
    }
    // An empty range becomes [0, 1]; a single value gets a unit-wide window around it.
    Range settled(double padFraction) const {
        if (!(low <= high)) {
            return {0.0, 1.0};
        }
        if (high - low <= 1e-12 * std::max(1.0, std::abs(high))) {
            return {low - 0.5, high + 0.5};
        }
        const double pad = padFraction * (high - low);
        return {low - pad, high + pad};
    }
};

std::string px(double value) {
    return formatTrimmed(value, 1);
}

class Canvas {
  public:
    Canvas(const Plot& plot, Range x, Range y)
        : m_plot(plot), m_x(x), m_y(y), m_innerWidth(plot.width - kLeft - kRight),
          m_innerHeight(plot.height - kTop - kBottom) {}

    double mapX(double value) const {
        return kLeft + (value - m_x.low) / (m_x.high - m_x.low) * m_innerWidth;
    }
    double mapY(double value) const {
        return kTop + (m_y.high - value) / (m_y.high - m_y.low) * m_innerHeight;
    }
    int columns() const { return std::max(1, static_cast<int>(m_innerWidth)); }
    const Range& x() const { return m_x; }
    const Range& y() const { return m_y; }
    const Plot& plot() const { return m_plot; }

  private:
    const Plot& m_plot;
    Range m_x, m_y;
    double m_innerWidth, m_innerHeight;
};

// Indices to draw: all of them for short series; otherwise, per bucket of consecutive points,
// the minimum and the maximum in their original order (peaks survive, the shape is kept).
std::vector<std::size_t> pointsToDraw(const std::vector<double>& y, int columns) {
    const std::size_t n = y.size();
    const std::size_t buckets = 2 * static_cast<std::size_t>(columns);
    std::vector<std::size_t> kept;
    if (n <= 2 * buckets) {
        kept.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            kept[i] = i;
        }
        return kept;
    }
    for (std::size_t b = 0; b < buckets; ++b) {
        const std::size_t begin = b * n / buckets, end = (b + 1) * n / buckets;
        std::size_t lo = begin, hi = begin;
        for (std::size_t i = begin; i < end; ++i) {
            if (!std::isfinite(y[i])) {
                continue;
            }
            lo = (!std::isfinite(y[lo]) || y[i] < y[lo]) ? i : lo;
            hi = (!std::isfinite(y[hi]) || y[i] > y[hi]) ? i : hi;
        }
        kept.push_back(std::min(lo, hi));
        if (lo != hi) {
            kept.push_back(std::max(lo, hi));
        }
    }
    return kept;
}

std::string polylinePath(const Canvas& canvas, const std::vector<double>& x,
                         const std::vector<double>& y) {
    std::string d;
    bool penDown = false;
    const std::size_t n = std::min(x.size(), y.size());
    for (std::size_t i : pointsToDraw(y, canvas.columns())) {
        if (i >= n || !std::isfinite(x[i]) || !std::isfinite(y[i])) {
            penDown = false;
            continue;
        }
        d += (penDown ? "L" : "M") + px(canvas.mapX(x[i])) + " " + px(canvas.mapY(y[i]));
        penDown = true;
    }
    return d;
}

std::string bandPath(const Canvas& canvas, const PlotBand& band) {
    const std::size_t n = std::min({band.x.size(), band.lower.size(), band.upper.size()});
    std::string d;
    for (std::size_t i : pointsToDraw(band.upper, canvas.columns())) {
        if (i < n && std::isfinite(band.x[i]) && std::isfinite(band.upper[i])) {
            d += (d.empty() ? "M" : "L") + px(canvas.mapX(band.x[i])) + " " +
                 px(canvas.mapY(band.upper[i]));
        }
    }
    auto lower = pointsToDraw(band.lower, canvas.columns());
    for (auto it = lower.rbegin(); it != lower.rend(); ++it) {
        if (*it < n && std::isfinite(band.x[*it]) && std::isfinite(band.lower[*it])) {
            d += "L" + px(canvas.mapX(band.x[*it])) + " " + px(canvas.mapY(band.lower[*it]));
        }
    }
    return d.empty() ? d : d + "Z";
}

int decimalsFor(const std::vector<double>& ticks) {
    if (ticks.size() < 2) {
        return 0;
    }
    const double step = std::abs(ticks[1] - ticks[0]);
    return std::clamp(static_cast<int>(std::ceil(-std::log10(step))), 0, 8);
}

std::string axesSvg(const Canvas& canvas) {
    const Plot& plot = canvas.plot();
    const double left = kLeft, right = plot.width - kRight;
    const double top = kTop, bottom = plot.height - kBottom;
    std::string svg;
    const auto xTicks = niceTicks(canvas.x().low, canvas.x().high, 8);
    const auto yTicks = niceTicks(canvas.y().low, canvas.y().high, 6);
    for (double t : xTicks) {
        const std::string at = px(canvas.mapX(t));
        svg += "<line x1=\"" + at + "\" y1=\"" + px(top) + "\" x2=\"" + at + "\" y2=\"" +
               px(bottom) + "\" stroke=\"#e4e4e4\"/>";
        svg += "<text x=\"" + at + "\" y=\"" + px(bottom + 16) + "\" text-anchor=\"middle\">" +
               formatTrimmed(t, decimalsFor(xTicks)) + "</text>";
    }
    for (double t : yTicks) {
        const std::string at = px(canvas.mapY(t));
        svg += "<line x1=\"" + px(left) + "\" y1=\"" + at + "\" x2=\"" + px(right) + "\" y2=\"" +
               at + "\" stroke=\"#e4e4e4\"/>";
        svg += "<text x=\"" + px(left - 6) + "\" y=\"" + at +
               "\" text-anchor=\"end\" dominant-baseline=\"middle\">" +
               formatTrimmed(t, decimalsFor(yTicks)) + "</text>";
    }
    svg += "<rect x=\"" + px(left) + "\" y=\"" + px(top) + "\" width=\"" + px(right - left) +
           "\" height=\"" + px(bottom - top) + "\" fill=\"none\" stroke=\"#888\"/>";
    svg += "<text x=\"" + px((left + right) / 2) + "\" y=\"" + px(plot.height - 6.0) +
           "\" text-anchor=\"middle\">" + escapeMarkup(plot.xLabel) + "</text>";
    svg += "<text transform=\"translate(14 " + px((top + bottom) / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escapeMarkup(plot.yLabel) + "</text>";
    svg += "<text x=\"" + px(left) + "\" y=\"18\" font-weight=\"bold\">" +
           escapeMarkup(plot.title) + "</text>";
    return svg;
}

std::string legendSvg(const Plot& plot, const std::vector<std::string>& colours) {
    std::string svg;
    double x = plot.width - kRight;
    // Right-aligned, last entry first, so entries grow leftwards from the frame's corner.
    for (std::size_t k = plot.series.size(); k-- > 0;) {
        const std::string& name = plot.series[k].name;
        const double width = 26.0 + 6.5 * static_cast<double>(name.size());
        x -= width;
        svg += "<line x1=\"" + px(x) + "\" y1=\"14\" x2=\"" + px(x + 18) +
               "\" y2=\"14\" stroke=\"" + colours[k] + "\" stroke-width=\"2\"" +
               (plot.series[k].dashed ? " stroke-dasharray=\"5 3\"" : "") + "/>";
        svg += "<text x=\"" + px(x + 22) + "\" y=\"18\">" + escapeMarkup(name) + "</text>";
    }
    return svg;
}

} // namespace

std::vector<double> niceTicks(double low, double high, int count) {
    if (!(high > low) || count < 1 || !std::isfinite(low) || !std::isfinite(high)) {
        return {};
    }
    const double rough = (high - low) / count;
    const double magnitude = std::pow(10.0, std::floor(std::log10(rough)));
    double step = magnitude;
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        step = factor * magnitude;
        if (step >= rough) {
            break;
        }
    }
    std::vector<double> ticks;
    for (double t = std::ceil(low / step) * step; t <= high + 1e-9 * step; t += step) {
        ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    }
    return ticks;
}

std::string renderSvg(const Plot& plot) {
    Range x, y;
    for (const PlotSeries& series : plot.series) {
        x.addAll(series.x);
        y.addAll(series.y);
    }
    for (const PlotBand& band : plot.bands) {
        x.addAll(band.x);
        y.addAll(band.lower);
        y.addAll(band.upper);
    }
    const Canvas canvas(plot, x.settled(0.0), y.settled(0.05));
    std::vector<std::string> colours;
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
        colours.push_back(plot.series[k].colour.empty() ? kPalette[k % kPalette.size()]
                                                        : plot.series[k].colour);
    }
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(plot.width) + "\" height=\"" + std::to_string(plot.height) +
                      "\" viewBox=\"0 0 " + std::to_string(plot.width) + " " +
                      std::to_string(plot.height) +
                      "\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"11\">";
    // Styled by attributes, not CSS classes: the figure looks the same on its own.
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>";
    svg += axesSvg(canvas);
    // A nested viewport clips the curves to the frame without document-wide ids, so any number
    // of plots can share one HTML page.
    const std::string inner = px(kLeft) + " " + px(kTop) + " " + px(plot.width - kLeft - kRight) +
                              " " + px(plot.height - kTop - kBottom);
    svg += "<svg x=\"" + px(kLeft) + "\" y=\"" + px(kTop) + "\" width=\"" +
           px(plot.width - kLeft - kRight) + "\" height=\"" + px(plot.height - kTop - kBottom) +
           "\" viewBox=\"" + inner + "\">";
    for (const PlotBand& band : plot.bands) {
        svg += "<path d=\"" + bandPath(canvas, band) + "\" fill=\"" + band.colour +
               "\" fill-opacity=\"" + formatTrimmed(band.opacity, 3) +
               "\" stroke=\"none\"><title>" + escapeMarkup(band.name) + "</title></path>";
    }
    for (std::size_t k = 0; k < plot.series.size(); ++k) {
        const PlotSeries& series = plot.series[k];
        svg += "<path d=\"" + polylinePath(canvas, series.x, series.y) +
               "\" fill=\"none\" stroke=\"" + colours[k] + "\" stroke-width=\"1.4\"" +
               (series.dashed ? " stroke-dasharray=\"5 3\"" : "") + "><title>" +
               escapeMarkup(series.name) + "</title></path>";
    }
    svg += "</svg>" + legendSvg(plot, colours) + "</svg>";
    return svg;
}

} // namespace bladeaxis::report

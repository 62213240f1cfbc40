#include "core/report/html_page.h"
#include "core/report/svg_plot.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <limits>
#include <string>

namespace bladeaxis::report {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

Plot sinePlot(std::size_t points) {
    PlotSeries series{.name = "A velocity", .x = {}, .y = {}, .colour = {}, .dashed = false};
    for (std::size_t i = 0; i < points; ++i) {
        series.x.push_back(0.001 * static_cast<double>(i));
        series.y.push_back(std::sin(0.01 * static_cast<double>(i)));
    }
    Plot plot;
    plot.title = "A axis";
    plot.xLabel = "t (s)";
    plot.yLabel = "deg/s";
    plot.series.push_back(series);
    return plot;
}

TEST(NiceTicks, UseOneTwoFiveStepsInsideTheRange) {
    const auto ticks = niceTicks(-0.3, 9.7, 5);
    ASSERT_GE(ticks.size(), 4u);
    EXPECT_DOUBLE_EQ(ticks[1] - ticks[0], 2.0);
    EXPECT_GE(ticks.front(), -0.3);
    EXPECT_LE(ticks.back(), 9.7);
    EXPECT_TRUE(niceTicks(1.0, 1.0, 5).empty());
    EXPECT_TRUE(niceTicks(0.0, std::numeric_limits<double>::infinity(), 5).empty());
}

TEST(SvgPlot, IsOneWellFormedDrawingWithLegendAndLabels) {
    const std::string svg = renderSvg(sinePlot(200));
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_EQ(count(svg, "<svg"), count(svg, "</svg>"));
    EXPECT_NE(svg.find("A velocity"), std::string::npos);
    EXPECT_NE(svg.find("deg/s"), std::string::npos);
    EXPECT_EQ(svg.find("id="), std::string::npos) << "ids would clash between plots of one page";
}

TEST(SvgPlot, MillionPointSeriesKeepsItsPeakAndStaysSmall) {
    Plot plot = sinePlot(1'000'000);
    plot.series[0].y[612'345] = 40.0; // a single-sample spike must not vanish in the reduction
    const std::string svg = renderSvg(plot);
    EXPECT_LT(svg.size(), 200'000u);
    EXPECT_NE(svg.find(">40<"), std::string::npos) << "the y ticks reach the spike";
    const std::string withoutSpike = renderSvg(sinePlot(1'000'000));
    EXPECT_EQ(withoutSpike.find(">40<"), std::string::npos);
}

TEST(SvgPlot, NonFiniteValuesBreakTheLine) {
    Plot plot = sinePlot(50);
    plot.series[0].y[20] = std::numeric_limits<double>::quiet_NaN();
    const std::string svg = renderSvg(plot);
    const std::size_t path = svg.find("<path d=\"");
    ASSERT_NE(path, std::string::npos);
    const std::string d = svg.substr(path, svg.find('"', path + 9) - path);
    EXPECT_EQ(count(d, "M"), 2u);
    EXPECT_EQ(d.find_first_not_of("ML0123456789. -", 9), std::string::npos) << d;
}

TEST(SvgPlot, BandIsAClosedArea) {
    Plot plot;
    plot.bands.push_back(PlotBand{.name = "channel",
                                  .x = {0, 1, 2},
                                  .lower = {-1, -1, 0},
                                  .upper = {1, 2, 2},
                                  .colour = "#9ecae1",
                                  .opacity = 0.3});
    const std::string svg = renderSvg(plot);
    EXPECT_NE(svg.find("Z\" fill=\"#9ecae1\""), std::string::npos);
}

TEST(SvgPlot, DoesNotDependOnADecimalCommaLocale) {
    const std::string inC = renderSvg(sinePlot(300));
    const std::string saved = std::setlocale(LC_ALL, nullptr);
    if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr) {
        GTEST_SKIP() << "de_DE.UTF-8 is not installed (packaging/install-deps.sh generates it)";
    }
    const std::string inGerman = renderSvg(sinePlot(300));
    std::setlocale(LC_ALL, saved.c_str());
    EXPECT_EQ(inC, inGerman);
}

TEST(HtmlPage, IsSelfContainedAndEscapesText) {
    HtmlPage page("Blade <B12> & co");
    page.paragraph("A < B");
    page.table({"method", "peak A acc. (deg/s^2)"}, {{"original", "418181"}, {"s-theta", "1176"}});
    page.figure(sinePlot(100), "A velocity against time");
    const std::string html = page.str();
    EXPECT_NE(html.find("Blade &lt;B12&gt; &amp; co"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"num\">418181</td>"), std::string::npos);
    EXPECT_NE(html.find("<td>original</td>"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("src="), std::string::npos);
    EXPECT_EQ(html.find("href="), std::string::npos);
    EXPECT_NE(html.find("<svg"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::report

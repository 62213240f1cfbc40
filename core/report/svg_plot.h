#pragma once
// Line plots as self-contained SVG text: the HTML report's figures are rendered with no display,
// no browser scripting and no plotting library, so `--batch` can write them on a headless node.

#include <string>
#include <vector>

namespace bladeaxis::report {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y; // same length; non-finite points break the line
    std::string colour;       // CSS colour; empty: taken from the palette in order
    bool dashed = false;
};

// A filled region between two curves over the same x, e.g. a feasible channel.
struct PlotBand {
    std::string name;
    std::vector<double> x, lower, upper;
    std::string colour = "#9ecae1";
    double opacity = 0.35;
};

struct Plot {
    std::string title, xLabel, yLabel;
    std::vector<PlotBand> bands; // drawn first, under the series
    std::vector<PlotSeries> series;
    int width = 760, height = 300; // px
};

// Series longer than the plot is wide are reduced to the minimum and maximum per pixel column,
// so a million-point axis trace keeps every peak and the SVG stays small.
std::string renderSvg(const Plot& plot);

// "Nice" tick values (1, 2, 5 x 10^k steps) covering [low, high], about `count` of them.
std::vector<double> niceTicks(double low, double high, int count);

} // namespace bladeaxis::report

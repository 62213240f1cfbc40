#pragma once
// What the GUI tests look for in rendered images, and the demo job they render.

#include "core/job/job.h"

#include <QColor>
#include <QImage>
#include <QtGlobal>
#include <cstdlib>
#include <set>

namespace bladeaxis::gui_test {

// Distinct colours among every `step`-th pixel: a blank (unpainted) widget has one or two.
inline std::size_t distinctColours(const QImage& image, int step = 1) {
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += step) {
        for (int x = 0; x < image.width(); x += step) {
            colours.insert(image.pixel(x, y));
        }
    }
    return colours.size();
}

// Pixels whose red, green and blue each lie within `tolerance` of `colour` (antialiasing blends
// line edges; 0 counts exact matches).
inline std::size_t pixelsNear(const QImage& image, const QColor& colour, int tolerance) {
    std::size_t count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            const bool near = std::abs(c.red() - colour.red()) <= tolerance &&
                              std::abs(c.green() - colour.green()) <= tolerance &&
                              std::abs(c.blue() - colour.blue()) <= tolerance;
            count += near ? 1U : 0U;
        }
    }
    return count;
}

// The share of pixels that are not the background colour.
inline double shareDifferentFrom(const QImage& image, QRgb background) {
    std::size_t covered = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            covered += image.pixel(x, y) != background ? 1U : 0U;
        }
    }
    return static_cast<double>(covered) / static_cast<double>(image.width() * image.height());
}

// The demo job through core, as the GUI runs it; a failure ends the test run.
inline job::JobResult runDemoJob(bool compare) {
    job::JobSpec spec;
    spec.demo = true;
    spec.compare = compare;
    NullProgressSink progress;
    CancelToken cancel;
    auto result = job::runJob(spec, progress, cancel);
    if (!result) {
        qFatal("demo job failed: %s", result.error().toString().c_str());
    }
    return std::move(*result);
}

} // namespace bladeaxis::gui_test

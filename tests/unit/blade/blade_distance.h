#pragma once
// Distance from a point to a blade's surface, the union of its sections {x'} x C(x'), by a scan
// over x' (0.02 mm steps, then 0.5 um steps around the best): a reference independent of the
// generator's surface normals.

#include "core/blade/blade.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::blade::testing {

inline double distanceToBlade(const Blade& blade, const Vec3& q, double reach = 9.0) {
    auto at = [&](double x) {
        return std::hypot(x - q.x(), distanceToCurve(q.tail<2>(), blade.sectionAt(x)));
    };
    const double from = std::max(blade.spanStart(), q.x() - reach);
    const double to = std::min(blade.spanEnd(), q.x() + reach);
    double bestX = from;
    double best = at(from);
    for (double x = from; x <= to; x += 0.02) {
        if (const double d = at(x); d < best) {
            best = d;
            bestX = x;
        }
    }
    for (double x = std::max(from, bestX - 0.02); x <= std::min(to, bestX + 0.02); x += 5e-4) {
        best = std::min(best, at(x));
    }
    return best;
}

} // namespace bladeaxis::blade::testing

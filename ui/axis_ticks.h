#pragma once
// Round tick values for the window's plots: steps of 1, 2 or 5 times a power of ten, so an axis
// reads 0, 50, 100 rather than 44, 118, 192.

#include <QString>
#include <vector>

namespace bladeaxis::ui {

// Tick spacing of 1, 2 or 5 times a power of ten giving at most about `maxTicks` ticks over
// `range` (> 0).
double niceStep(double range, int maxTicks);

// The multiples of niceStep(high - low, maxTicks) inside [low, high].
std::vector<double> niceTicks(double low, double high, int maxTicks);

// A tick value with as many decimals as the step needs; thousands as "k" from a step of 1000 so
// acceleration labels stay narrow.
QString tickLabel(double value, double step);

} // namespace bladeaxis::ui

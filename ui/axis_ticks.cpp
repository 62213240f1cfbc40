#include "ui/axis_ticks.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::ui {

double niceStep(double range, int maxTicks) {
    const double rough = range / std::max(maxTicks, 1);
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (double factor : {1.0, 2.0, 5.0}) {
        if (factor * power >= rough) {
            return factor * power;
        }
    }
    return 10.0 * power;
}

std::vector<double> niceTicks(double low, double high, int maxTicks) {
    std::vector<double> ticks;
    if (!(high > low) || !std::isfinite(low) || !std::isfinite(high)) {
        return ticks;
    }
    const double step = niceStep(high - low, maxTicks);
    // Counted in whole steps, so accumulated rounding neither skips nor adds the last tick.
    const auto first = static_cast<long long>(std::ceil(low / step - 1e-9));
    const auto last = static_cast<long long>(std::floor(high / step + 1e-9));
    for (long long k = first; k <= last; ++k) {
        ticks.push_back(static_cast<double>(k) * step);
    }
    return ticks;
}

QString tickLabel(double value, double step) {
    if (std::abs(value) < step * 1e-6) {
        return QStringLiteral("0");
    }
    if (step >= 1000.0) {
        return QString::number(value / 1000.0, 'f', step >= 10000.0 ? 0 : 1) + QLatin1Char('k');
    }
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step))));
    return QString::number(value, 'f', decimals);
}

} // namespace bladeaxis::ui

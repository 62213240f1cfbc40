#include "core/scheduling/detail/corner_channel.h"

#include <algorithm>

namespace bladeaxis::scheduling::detail {

std::size_t ChannelView::lowerIndex(double x) const {
    return static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), x) - s.begin());
}

std::size_t ChannelView::upperIndex(double x) const {
    return static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), x) - s.begin());
}

std::pair<double, double> ChannelView::at(double x) const {
    const std::size_t j = std::clamp<std::size_t>(upperIndex(x), 1, s.size() - 1);
    const double w = std::clamp((x - s[j - 1]) / (s[j] - s[j - 1]), 0.0, 1.0);
    return {rawMin[j - 1] + w * (rawMin[j] - rawMin[j - 1]) + clearance,
            rawMax[j - 1] + w * (rawMax[j] - rawMax[j - 1]) - clearance};
}

bool pairFeasible(const BezierPair& pair, const ChannelView& channel, int checks) {
    const std::size_t end = channel.upperIndex(pair.sEnd());
    for (std::size_t j = channel.lowerIndex(pair.sBegin()); j < end; ++j) {
        const double value = evaluatePair(pair, channel.s[j]).value;
        if (value < channel.rawMin[j] + channel.clearance - kFeasibilityTolerance ||
            value > channel.rawMax[j] - channel.clearance + kFeasibilityTolerance) {
            return false;
        }
    }
    for (const CubicBezier* cubic : {&pair.first, &pair.second}) {
        for (int k = 0; k <= checks; ++k) {
            const Vec2 p = cubic->point(static_cast<double>(k) / checks);
            const auto [low, high] = channel.at(p.x());
            if (p.y() < low - kFeasibilityTolerance || p.y() > high + kFeasibilityTolerance) {
                return false;
            }
        }
    }
    return true;
}

} // namespace bladeaxis::scheduling::detail

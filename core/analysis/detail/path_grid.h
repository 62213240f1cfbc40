#pragma once
// The grid T2's constraints hold on: each interval between two profile samples cut into a number
// of equal steps, the same for every interval or chosen per interval (a refinement that cuts
// only the blocks where the time still moves).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace bladeaxis::analysis::detail {

class PathGrid {
  public:
    // Every interval of `s` (the profile's path parameter) in `steps` steps.
    PathGrid(const std::vector<double>& s, std::size_t steps) : m_s(s), m_uniform(steps) {}

    // Interval i in stepsPerInterval[i] steps (one entry per interval, each >= 1).
    PathGrid(const std::vector<double>& s, std::span<const std::uint32_t> stepsPerInterval)
        : m_s(s) {
        m_first.reserve(stepsPerInterval.size() + 1);
        std::uint32_t point = 0;
        for (std::size_t i = 0; i < stepsPerInterval.size(); ++i) {
            m_first.push_back(point);
            for (std::uint32_t k = 0; k < stepsPerInterval[i]; ++k) {
                m_intervalOf.push_back(static_cast<std::uint32_t>(i));
            }
            point += stepsPerInterval[i];
        }
        m_first.push_back(point);
        m_intervalOf.push_back(static_cast<std::uint32_t>(stepsPerInterval.size()));
    }

    std::size_t size() const {
        return uniform() ? (m_s.size() - 1) * m_uniform + 1 : m_intervalOf.size();
    }
    // The interval grid point g lies in (the last point: the last sample's index).
    std::size_t interval(std::size_t g) const {
        return uniform() ? g / m_uniform : m_intervalOf[g];
    }
    std::size_t stepsIn(std::size_t interval) const {
        return uniform() ? m_uniform : m_first[interval + 1] - m_first[interval];
    }
    std::size_t firstPoint(std::size_t interval) const {
        return uniform() ? interval * m_uniform : m_first[interval];
    }
    // How far through its interval grid point g lies, in [0, 1).
    double fraction(std::size_t g) const {
        const std::size_t i = interval(g);
        if (i + 1 >= m_s.size()) {
            return 0.0;
        }
        return static_cast<double>(g - firstPoint(i)) / static_cast<double>(stepsIn(i));
    }
    // The length of the step from grid point g to g + 1, mm.
    double step(std::size_t g) const {
        const std::size_t i = interval(g);
        return (m_s[i + 1] - m_s[i]) / static_cast<double>(stepsIn(i));
    }
    double pathAt(std::size_t g) const {
        const std::size_t i = interval(g);
        return i + 1 >= m_s.size() ? m_s[i] : m_s[i] + fraction(g) * (m_s[i + 1] - m_s[i]);
    }

  private:
    bool uniform() const { return m_uniform > 0; }

    const std::vector<double>& m_s;
    std::size_t m_uniform = 0;               // > 0: every interval in this many steps
    std::vector<std::uint32_t> m_first;      // per interval, its first grid point
    std::vector<std::uint32_t> m_intervalOf; // per grid point, its interval
};

} // namespace bladeaxis::analysis::detail

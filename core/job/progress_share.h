#pragma once
// A stage's share of a job's progress.

#include "core/base/progress.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

namespace bladeaxis::job {

// A stage's share [from, to] of a job's progress. What the stage reports within it reaches the
// sink only when the whole percent or the stage's text changes: a large read reports about a
// thousand times.
class ProgressShare {
  public:
    ProgressShare(ProgressSink& sink, double from, double to)
        : m_sink(sink), m_from(from), m_to(to) {}

    void report(double done, std::string_view stage) {
        const double fraction = m_from + std::clamp(done, 0.0, 1.0) * (m_to - m_from);
        const int percent = static_cast<int>(std::floor(100.0 * fraction));
        if (percent == m_shownPercent && stage == m_shownStage) {
            return;
        }
        m_shownPercent = percent;
        m_shownStage = stage;
        m_sink.progress(fraction, stage);
    }

  private:
    ProgressSink& m_sink;
    double m_from, m_to;
    int m_shownPercent = -1;
    std::string m_shownStage;
};

} // namespace bladeaxis::job

#include "core/analysis/reversals.h"

#include "core/geometry/angles.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::analysis {

ReversalAudit auditReversals(std::span<const double> a, double minStep) {
    ReversalAudit audit;
    double forward = 0.0;
    double backward = 0.0;
    int direction = 0; // sign of the last step that counted; 0 before the first one
    for (std::size_t i = 1; i < a.size(); ++i) {
        const double step = a[i] - a[i - 1];
        if (!std::isfinite(step)) {
            continue;
        }
        (step > 0.0 ? forward : backward) += std::abs(step);
        if (!(std::abs(step) > minStep)) {
            continue;
        }
        const int sign = step > 0.0 ? 1 : -1;
        if (direction != 0 && sign != direction) {
            ++audit.count;
            audit.indices.push_back(i - 1);
        }
        direction = sign;
    }
    audit.travel = forward + backward;
    audit.backwardTravel = std::min(forward, backward);
    return audit;
}

std::vector<double> unwrapRotary(std::span<const double> a) {
    std::vector<double> result(a.begin(), a.end());
    bool haveReference = false;
    double reference = 0.0;
    for (double& value : result) {
        if (!std::isfinite(value)) {
            continue;
        }
        if (haveReference) {
            value = geometry::unwrapNear(value, reference);
        }
        reference = value;
        haveReference = true;
    }
    return result;
}

} // namespace bladeaxis::analysis

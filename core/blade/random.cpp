#include "core/blade/random.h"

#include "core/base/units.h"

#include <cmath>

namespace bladeaxis::blade {

double Random::uniform() {
    // The top 53 bits fill the double mantissa exactly; the result is k / 2^53.
    const std::uint64_t bits = m_engine() >> 11;
    return static_cast<double>(bits) * 0x1.0p-53;
}

double Random::normal() {
    // 1 - uniform() lies in (0, 1], so the logarithm is finite.
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(units::kTwoPi * u2);
}

int Random::index(int count) {
    if (count <= 1) {
        return 0;
    }
    const int value = static_cast<int>(uniform() * count);
    return value < count ? value : count - 1;
}

} // namespace bladeaxis::blade

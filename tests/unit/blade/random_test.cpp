#include "core/blade/random.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::blade {
namespace {

TEST(Random, UniformStaysInTheUnitIntervalWithMeanOneHalf) {
    Random random(42);
    double sum = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double u = random.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    // Standard error of the mean: sqrt(1/12 / n) = 0.0009.
    EXPECT_NEAR(sum / n, 0.5, 0.005);
}

TEST(Random, NormalHasZeroMeanAndUnitVariance) {
    Random random(7);
    double sum = 0.0;
    double squares = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double z = random.normal();
        ASSERT_TRUE(std::isfinite(z));
        sum += z;
        squares += z * z;
    }
    EXPECT_NEAR(sum / n, 0.0, 0.02);
    EXPECT_NEAR(squares / n, 1.0, 0.03);
}

TEST(Random, SameSeedSameStreamDifferentSeedDifferentStream) {
    Random a(3);
    Random b(3);
    Random c(4);
    bool differs = false;
    for (int i = 0; i < 10; ++i) {
        const double x = a.uniform();
        EXPECT_EQ(x, b.uniform());
        differs = differs || x != c.uniform();
    }
    EXPECT_TRUE(differs);
}

TEST(Random, IndexCoversTheRangeAndNothingElse) {
    Random random(1);
    int seen[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i < 1000; ++i) {
        const int k = random.index(5);
        ASSERT_GE(k, 0);
        ASSERT_LT(k, 5);
        ++seen[k];
    }
    for (int count : seen) {
        EXPECT_GT(count, 100);
    }
    EXPECT_EQ(random.index(0), 0);
}

} // namespace
} // namespace bladeaxis::blade

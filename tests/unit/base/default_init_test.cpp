#include "core/base/default_init.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace bladeaxis {
namespace {

TEST(DefaultInitVector, GrowingKeepsTheExistingValues) {
    DefaultInitVector<double> values{1.0, 2.0, 3.0};
    values.resize(1000);
    ASSERT_EQ(values.size(), 1000u);
    EXPECT_EQ(values[0], 1.0);
    EXPECT_EQ(values[1], 2.0);
    EXPECT_EQ(values[2], 3.0);
}

TEST(DefaultInitVector, FillsWhereAValueIsGiven) {
    DefaultInitVector<int> values(5, 7);
    EXPECT_EQ(values, DefaultInitVector<int>(5, 7));
    values.resize(8, -1);
    EXPECT_EQ(values, (DefaultInitVector<int>{7, 7, 7, 7, 7, -1, -1, -1}));
    values.assign(3, 4);
    EXPECT_EQ(values, (DefaultInitVector<int>{4, 4, 4}));
    values.push_back(9);
    EXPECT_EQ(values.back(), 9);
}

struct WithDefault {
    int value = 42;
};

TEST(DefaultInitVector, RunsTheDefaultConstructorOfClassTypes) {
    DefaultInitVector<WithDefault> values(4);
    values.resize(10);
    for (const WithDefault& element : values) {
        EXPECT_EQ(element.value, 42);
    }
}

TEST(DefaultInitVector, LargeArraysHoldTheirValuesThroughCopiesAndGrowth) {
    const std::size_t count = (std::size_t{8} << 20) / sizeof(std::uint64_t) + 123;
    DefaultInitVector<std::uint64_t> values(count);
    std::iota(values.begin(), values.end(), std::uint64_t{5});
    const DefaultInitVector<std::uint64_t> copy = values;
    values.resize(2 * count);
    values.resize(count);
    values.shrink_to_fit();
    EXPECT_EQ(values, copy);
    EXPECT_EQ(copy.front(), 5u);
    EXPECT_EQ(copy.back(), count + 4);
}

} // namespace
} // namespace bladeaxis

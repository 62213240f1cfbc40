#include "core/base/order_statistic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace bladeaxis {
namespace {

double referenceNth(std::vector<double> values, std::size_t k) {
    std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
    return values[k];
}

// Checks the first, the median, a quartile and the last rank on 1, 2 and 3 threads.
void expectSameAsNthElement(const std::vector<double>& values) {
    const std::size_t n = values.size();
    for (std::size_t k : {std::size_t{0}, n / 4, n / 2, n - 1}) {
        const double expected = referenceNth(values, k);
        for (unsigned threads : {1u, 2u, 3u}) {
            const ThreadCountScope scope(threads);
            const double got = nthSmallest(n, k, [&values](std::size_t i) { return values[i]; });
            EXPECT_EQ(got, expected) << "k " << k << ", threads " << threads;
        }
    }
}

constexpr std::size_t kLarge = 3 * detail::kMinSampledSelection + 17;

TEST(OrderStatistic, RandomValuesGiveWhatNthElementGives) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-5.0, 5.0);
    std::vector<double> values(kLarge);
    for (double& value : values) {
        value = uniform(random);
    }
    expectSameAsNthElement(values);
}

TEST(OrderStatistic, ValuesRepeatingWithThePathsPeriodGiveWhatNthElementGives) {
    // Equal chords along each revolution, as a helical path's: strided samples would all see
    // the same phase.
    std::vector<double> values(kLarge);
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] =
            0.05 + 0.01 * std::sin(2.0 * std::numbers::pi * static_cast<double>(i % 1024) / 1024.0);
    }
    expectSameAsNthElement(values);
}

TEST(OrderStatistic, ManyEqualValuesGiveWhatNthElementGives) {
    std::vector<double> allEqual(kLarge, 0.25);
    expectSameAsNthElement(allEqual);
    std::vector<double> twoValues(kLarge);
    for (std::size_t i = 0; i < twoValues.size(); ++i) {
        twoValues[i] = i % 3 == 0 ? 1.0 : 2.0;
    }
    expectSameAsNthElement(twoValues);
    std::vector<double> fewDistinct(kLarge);
    for (std::size_t i = 0; i < fewDistinct.size(); ++i) {
        fewDistinct[i] = static_cast<double>((i * 7919) % 13);
    }
    expectSameAsNthElement(fewDistinct);
}

TEST(OrderStatistic, SmallInputsGiveWhatNthElementGives) {
    std::vector<double> values;
    for (std::size_t i = 0; i < 1001; ++i) {
        values.push_back(std::cos(static_cast<double>(i)));
    }
    expectSameAsNthElement(values);
    const ThreadCountScope two(2);
    EXPECT_EQ(nthSmallest(1, 0, [](std::size_t) { return 3.5; }), 3.5);
}

// Values chosen against the sample: at every sampled position a value far beyond all the
// others, so the bracket misses the rank and the selection must fall back.
std::vector<double> valuesHidingTheRankFromTheSample(double sampledValue) {
    std::vector<double> values(kLarge);
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = static_cast<double>((i * 104729) % values.size());
    }
    for (std::uint64_t j = 0; j < detail::kSelectionSamples; ++j) {
        values[detail::samplePosition(j) % values.size()] = sampledValue;
    }
    return values;
}

TEST(OrderStatistic, ASampleThatMissesTheRankStillGivesTheExactValue) {
    expectSameAsNthElement(valuesHidingTheRankFromTheSample(1e9));
    expectSameAsNthElement(valuesHidingTheRankFromTheSample(-1e9));
}

TEST(OrderStatistic, AWellSpreadInputIsReadOncePastTheSample) {
    std::vector<double> values(kLarge);
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = 1.0 + 1e-3 * static_cast<double>(i % 977) + 1e-9 * static_cast<double>(i);
    }
    std::atomic<std::size_t> reads{0};
    const ThreadCountScope two(2);
    const double got = nthSmallest(values.size(), values.size() / 2, [&](std::size_t i) {
        ++reads;
        return values[i];
    });
    EXPECT_EQ(got, referenceNth(values, values.size() / 2));
    // No second pass over all values (the gathering fallback would read each again).
    EXPECT_EQ(reads.load(), detail::kSelectionSamples + values.size());
}

} // namespace
} // namespace bladeaxis

#pragma once
// The k-th smallest of many values computed on the fly, on several threads, with exactly the
// value std::nth_element gives (an order statistic is one value, whatever finds it).
//
// Why not nth_element: it reorders a materialised array on one thread (about 3.5 ns per value
// and 8 bytes of fresh memory per value), which is the longest serial step of the tangents on a
// million-point path. Here a sample brackets the k-th value, one parallel pass counts
// the values below the bracket and keeps those inside it (a few percent), and nth_element runs
// on those alone. When the sample misjudges the bracket (about one chance in 10^9 for values
// in any order), the values are all gathered and selected as before.

#include "core/base/default_init.h"
#include "core/base/parallel.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace bladeaxis {

namespace detail {

// Below this many values the plain selection is as fast as sampling.
inline constexpr std::size_t kMinSampledSelection = 4 * kMinParallelRange;
inline constexpr std::size_t kSelectionSamples = 4096;
// Sample positions kept on each side of the k-th one's sample rank. How many samples fall
// below the k-th value varies by about sqrt(samples)/2 = 32 (a binomial count); 192 leaves
// six of those on each side.
inline constexpr std::size_t kSelectionMargin = 192;

template <class ValueAt>
double nthSmallestGathered(std::size_t count, std::size_t k, const ValueAt& valueAt) {
    DefaultInitVector<double> values(count); // every value is written below
    forEachRange(count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            values[i] = valueAt(i);
        }
    });
    const auto kth = values.begin() + static_cast<long>(k);
    std::nth_element(values.begin(), kth, values.end());
    return *kth;
}

struct Bracket {
    double low = 0.0;
    double high = 0.0;
};

// A fixed pseudo-random sequence (splitmix64): positions in no relation to the periodic
// structure of a toolpath, where equal strides would sample one phase of each revolution.
inline std::uint64_t samplePosition(std::uint64_t j) {
    std::uint64_t z = (j + 1) * 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

template <class ValueAt>
Bracket bracketFromSample(std::size_t count, std::size_t k, const ValueAt& valueAt) {
    std::vector<double> sample(kSelectionSamples);
    for (std::size_t j = 0; j < sample.size(); ++j) {
        sample[j] = valueAt(static_cast<std::size_t>(samplePosition(j) % count));
    }
    std::sort(sample.begin(), sample.end());
    const std::size_t rank = k * sample.size() / count;
    const std::size_t lowRank = rank > kSelectionMargin ? rank - kSelectionMargin : 0;
    const std::size_t highRank = std::min(rank + kSelectionMargin, sample.size() - 1);
    return {sample[lowRank], sample[highRank]};
}

// What one range of values holds relative to the bracket. The values equal to its ends are
// counted, not kept: a path's values often repeat one value (a constant tilt, equal steps),
// which may then be most of them.
struct RangeTally {
    std::size_t below = 0;      // values < low
    std::size_t atLow = 0;      // values == low
    std::size_t atHigh = 0;     // values == high > low
    std::vector<double> inside; // low < value < high
};

struct Tally {
    std::size_t below = 0, atLow = 0, atHigh = 0, inside = 0;
};

template <class ValueAt>
std::vector<RangeTally> tallyRanges(std::size_t count, const Bracket& bracket,
                                    const ValueAt& valueAt) {
    std::vector<RangeTally> tallies(rangeCount(count));
    forEachRangeOf(count, tallies.size(), [&](std::size_t r, std::size_t begin, std::size_t end) {
        RangeTally& tally = tallies[r];
        // About the bracket's share of the sample, so the kept values rarely move.
        tally.inside.reserve((end - begin) * (2 * kSelectionMargin + 64) / kSelectionSamples);
        const double low = bracket.low;
        const double high = bracket.high;
        for (std::size_t i = begin; i < end; ++i) {
            const double value = valueAt(i);
            if (value < low) {
                ++tally.below;
            } else if (value == low) {
                ++tally.atLow;
            } else if (value < high) {
                tally.inside.push_back(value);
            } else if (value == high) {
                ++tally.atHigh;
            }
        }
    });
    return tallies;
}

} // namespace detail

// The k-th smallest (0-based, k < count) of valueAt(0) .. valueAt(count - 1), as
// std::nth_element would give it, on the context's threads (parallel.h). valueAt must be
// callable from several threads at once and give the same value each time. Values must be
// ordered (no NaN).
template <class ValueAt>
double nthSmallest(std::size_t count, std::size_t k, const ValueAt& valueAt) {
    if (count < detail::kMinSampledSelection) {
        return detail::nthSmallestGathered(count, k, valueAt);
    }
    const detail::Bracket bracket = detail::bracketFromSample(count, k, valueAt);
    const std::vector<detail::RangeTally> tallies = detail::tallyRanges(count, bracket, valueAt);
    detail::Tally total;
    for (const detail::RangeTally& tally : tallies) {
        total.below += tally.below;
        total.atLow += tally.atLow;
        total.atHigh += tally.atHigh;
        total.inside += tally.inside.size();
    }
    if (k < total.below) {
        return detail::nthSmallestGathered(count, k, valueAt);
    }
    std::size_t rank = k - total.below;
    if (rank < total.atLow) {
        return bracket.low;
    }
    rank -= total.atLow;
    if (rank >= total.inside) {
        return rank - total.inside < total.atHigh ? bracket.high
                                                  : detail::nthSmallestGathered(count, k, valueAt);
    }
    std::vector<double> candidates;
    candidates.reserve(total.inside);
    for (const detail::RangeTally& tally : tallies) {
        candidates.insert(candidates.end(), tally.inside.begin(), tally.inside.end());
    }
    const auto kth = candidates.begin() + static_cast<long>(rank);
    std::nth_element(candidates.begin(), kth, candidates.end());
    return *kth;
}

} // namespace bladeaxis

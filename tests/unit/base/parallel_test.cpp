#include "core/base/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <future>
#include <mutex>
#include <new>
#include <numeric>
#include <set>
#include <thread>
#include <utility>
#include <vector>

namespace bladeaxis {
namespace {

TEST(Parallel, RangesCoverEveryIndexOnceInContiguousPieces) {
    const std::size_t count = 5 * kMinParallelRange + 3;
    std::vector<int> visits(count, 0);
    std::mutex lock;
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    const ThreadCountScope four(4);
    forEachRange(count, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            ++visits[i];
        }
        const std::lock_guard guard(lock);
        ranges.emplace_back(begin, end);
    });
    EXPECT_TRUE(std::all_of(visits.begin(), visits.end(), [](int v) { return v == 1; }));
    EXPECT_EQ(ranges.size(), 4u);
    std::sort(ranges.begin(), ranges.end());
    EXPECT_EQ(ranges.front().first, 0u);
    EXPECT_EQ(ranges.back().second, count);
    for (std::size_t r = 1; r < ranges.size(); ++r) {
        EXPECT_EQ(ranges[r].first, ranges[r - 1].second);
    }
}

TEST(Parallel, RangesRunOnSeveralThreads) {
    std::mutex lock;
    std::set<std::thread::id> threads;
    const ThreadCountScope two(2);
    forEachRange(4 * kMinParallelRange, [&](std::size_t, std::size_t) {
        const std::lock_guard guard(lock);
        threads.insert(std::this_thread::get_id());
    });
    EXPECT_EQ(threads.size(), 2u);
}

TEST(Parallel, SmallInputRunsOnTheCallingThreadInOneRange) {
    int calls = 0;
    const ThreadCountScope eight(8);
    forEachRange(kMinParallelRange - 1, [&](std::size_t begin, std::size_t end) {
        ++calls;
        EXPECT_EQ(begin, 0u);
        EXPECT_EQ(end, kMinParallelRange - 1);
        EXPECT_EQ(std::this_thread::get_id(), std::this_thread::get_id());
    });
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(rangeCount(kMinParallelRange - 1), 1u);
    EXPECT_EQ(rangeCount(0), 1u);
}

TEST(Parallel, EmptyInputCallsNothingHarmful) {
    std::size_t covered = 0;
    const ThreadCountScope four(4);
    forEachRange(0, [&](std::size_t begin, std::size_t end) { covered += end - begin; });
    EXPECT_EQ(covered, 0u);
    int items = 0;
    forEachItem(0, 0, [&](std::size_t) { ++items; });
    EXPECT_EQ(items, 0);
}

TEST(Parallel, EveryItemIsHandedOutOnce) {
    const std::size_t count = 37;
    std::vector<std::atomic<int>> visits(count);
    const ThreadCountScope three(3);
    forEachItem(count, 10 * kMinParallelRange, [&](std::size_t i) { ++visits[i]; });
    for (std::size_t i = 0; i < count; ++i) {
        EXPECT_EQ(visits[i].load(), 1) << i;
    }
}

TEST(Parallel, AnExceptionInAWorkerRangeReachesTheCaller) {
    const std::size_t count = 4 * kMinParallelRange;
    const ThreadCountScope four(4);
    EXPECT_THROW(forEachRange(count,
                              [count](std::size_t begin, std::size_t) {
                                  if (begin >= count / 2) {
                                      throw std::bad_alloc();
                                  }
                              }),
                 std::bad_alloc);
}

TEST(Parallel, TheFirstFailureOfTheWholeInputWinsAndEverythingBeforeItIsStepped) {
    const std::size_t count = 4 * kMinParallelRange;
    const std::size_t early = count / 2 + 5; // in a later range than the start
    const std::size_t late = count - 3;
    std::vector<char> stepped(count, 0);
    const ThreadCountScope four(4);
    const std::size_t failed = forEachUntilFirstFailure(count, [&](std::size_t i) {
        stepped[i] = 1;
        return i != early && i != late;
    });
    EXPECT_EQ(failed, early);
    EXPECT_TRUE(std::all_of(stepped.begin(), stepped.begin() + static_cast<long>(early + 1),
                            [](char s) { return s == 1; }));
    EXPECT_EQ(forEachUntilFirstFailure(count, [](std::size_t) { return true; }), count);
}

TEST(Parallel, RunBothRunsEachOnceOnItsOwnThreadWhenTwoAreAllowed) {
    std::thread::id first;
    std::thread::id second;
    int calls = 0;
    std::mutex lock;
    const ThreadCountScope two(2);
    runBoth(
        kMinParallelRange,
        [&] {
            const std::lock_guard guard(lock);
            first = std::this_thread::get_id();
            ++calls;
        },
        [&] {
            const std::lock_guard guard(lock);
            second = std::this_thread::get_id();
            ++calls;
        });
    EXPECT_EQ(calls, 2);
    EXPECT_NE(first, second);
    EXPECT_EQ(first, std::this_thread::get_id()); // the calling thread takes the first
}

TEST(Parallel, RunBothRunsInOrderOnTheCallingThreadWithOneThread) {
    std::vector<std::pair<int, std::thread::id>> calls;
    const ThreadCountScope one(1);
    runBoth(
        kMinParallelRange, [&] { calls.emplace_back(1, std::this_thread::get_id()); },
        [&] { calls.emplace_back(2, std::this_thread::get_id()); });
    ASSERT_EQ(calls.size(), 2u);
    EXPECT_EQ(calls[0].first, 1);
    EXPECT_EQ(calls[1].first, 2);
    EXPECT_EQ(calls[0].second, std::this_thread::get_id());
    EXPECT_EQ(calls[1].second, std::this_thread::get_id());
}

TEST(Parallel, RunBothKeepsWorkTooSmallForAThreadOnTheCallingThread) {
    std::vector<std::thread::id> callers;
    const ThreadCountScope two(2);
    runBoth(
        kMinParallelRange - 1, [&] { callers.push_back(std::this_thread::get_id()); },
        [&] { callers.push_back(std::this_thread::get_id()); });
    ASSERT_EQ(callers.size(), 2u);
    EXPECT_EQ(callers[0], std::this_thread::get_id());
    EXPECT_EQ(callers[1], std::this_thread::get_id());
}

TEST(Parallel, RunBothRethrowsOnTheCallingThreadOnceBothHaveEnded) {
    std::atomic<bool> secondRan{false};
    const ThreadCountScope two(2);
    EXPECT_THROW(runBoth(
                     kMinParallelRange, [] { throw std::bad_alloc(); }, [&] { secondRan = true; }),
                 std::bad_alloc);
    EXPECT_TRUE(secondRan);
}

TEST(Parallel, ZeroThreadsMeansEveryHardwareThread) {
    EXPECT_EQ(resolveThreadCount(0), std::max(1u, std::thread::hardware_concurrency()));
    EXPECT_EQ(resolveThreadCount(3), 3u);
    const ThreadCountScope all(0);
    EXPECT_EQ(currentThreadCount(), hardwareThreadCount());
}

TEST(ExecutionContext, WithoutAScopeAThreadRunsSerially) {
    EXPECT_EQ(currentThreadCount(), 1u);
    std::set<std::thread::id> threads;
    forEachRange(8 * kMinParallelRange,
                 [&](std::size_t, std::size_t) { threads.insert(std::this_thread::get_id()); });
    EXPECT_EQ(threads.size(), 1u);
    EXPECT_EQ(std::async(std::launch::async, [] { return currentThreadCount(); }).get(), 1u);
}

TEST(ExecutionContext, ScopesNestAndRestoreThePreviousCount) {
    {
        const ThreadCountScope three(3);
        EXPECT_EQ(currentThreadCount(), 3u);
        {
            const ThreadCountScope one(1);
            EXPECT_EQ(currentThreadCount(), 1u);
        }
        EXPECT_EQ(currentThreadCount(), 3u);
    }
    EXPECT_EQ(currentThreadCount(), 1u);
}

TEST(ExecutionContext, WorkerThreadsRunUnderTheStartersCount) {
    const ThreadCountScope three(3);
    std::mutex lock;
    std::vector<unsigned> counts;
    forEachRange(3 * kMinParallelRange, [&](std::size_t, std::size_t) {
        const std::lock_guard guard(lock);
        counts.push_back(currentThreadCount());
    });
    EXPECT_EQ(counts, std::vector<unsigned>(3, 3u));
}

TEST(ExecutionContext, RunAsyncCarriesTheStartersCount) {
    const ThreadCountScope two(2);
    auto started =
        runAsync([] { return std::pair(currentThreadCount(), std::this_thread::get_id()); });
    const auto [count, thread] = started.get();
    EXPECT_EQ(count, 2u);
    EXPECT_NE(thread, std::this_thread::get_id());
    // Deferred: later, on the thread that waits, still under the starter's count.
    auto deferred = runAsync(std::launch::deferred, [] {
        return std::pair(currentThreadCount(), std::this_thread::get_id());
    });
    {
        const ThreadCountScope one(1);
        const auto [laterCount, laterThread] = deferred.get();
        EXPECT_EQ(laterCount, 2u);
        EXPECT_EQ(laterThread, std::this_thread::get_id());
        EXPECT_EQ(currentThreadCount(), 1u); // the waiter's own count is back
    }
}

TEST(ExecutionContext, RunAsyncRethrowsOnTheWaiter) {
    auto failing = runAsync([]() -> int { throw std::bad_alloc(); });
    EXPECT_THROW(failing.get(), std::bad_alloc);
}

} // namespace
} // namespace bladeaxis

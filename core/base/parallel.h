#pragma once
// Data-parallel loops for the per-point stages of large toolpaths. Work is split into contiguous
// index ranges decided by the count and the thread count alone, each range writes only its own
// elements, and reductions are combined in range order: a parallel run gives the same bits as a
// serial one. Small inputs run on the calling thread, where starting threads would cost more
// than the work (a thread start is tens of microseconds; a point costs tens of nanoseconds).
// The thread count is the calling thread's context (execution.h): currentThreadCount(), 1
// unless a ThreadCountScope of the caller's says otherwise.

#include "core/base/execution.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace bladeaxis {

// Below this many elements per range a loop runs serially.
inline constexpr std::size_t kMinParallelRange = 16384;

// The number of ranges forEachRange splits `count` elements into on the context's threads.
inline std::size_t rangeCount(std::size_t count) {
    const std::size_t byWork = std::max<std::size_t>(1, count / kMinParallelRange);
    return std::min<std::size_t>(currentThreadCount(), byWork);
}

// Calls body(range, begin, end) for `ranges` contiguous ranges covering [0, count), one thread
// per range (the calling thread takes the first; the others run under its thread count). An
// exception in any range (out of memory) is rethrown on the calling thread once every range has
// ended, as a serial loop would throw it, instead of terminating the process from a worker thread.
template <class Body>
void forEachRangeOf(std::size_t count, std::size_t ranges, Body&& body) {
    if (ranges == 1) { // the common case of small inputs: no thread, nothing to allocate
        body(std::size_t{0}, std::size_t{0}, count);
        return;
    }
    const auto bounds = [count, ranges](std::size_t r) { return count * r / ranges; };
    std::vector<std::exception_ptr> failures(ranges);
    const auto run = [&](std::size_t r) {
        try {
            body(r, bounds(r), bounds(r + 1));
        } catch (...) {
            failures[r] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(ranges > 0 ? ranges - 1 : 0);
    const unsigned threads = currentThreadCount();
    for (std::size_t r = 1; r < ranges; ++r) {
        pool.emplace_back([&run, threads, r] {
            ThreadCountScope scope(threads);
            run(r);
        });
    }
    if (ranges > 0) {
        run(0);
    }
    for (std::thread& thread : pool) {
        thread.join();
    }
    for (const std::exception_ptr& failure : failures) {
        if (failure) {
            std::rethrow_exception(failure);
        }
    }
}

// Calls body(begin, end) over [0, count) in contiguous ranges on up to the context's thread
// count; serially when the input is small.
template <class Body>
void forEachRange(std::size_t count, Body&& body) {
    forEachRangeOf(count, rangeCount(count),
                   [&body](std::size_t, std::size_t begin, std::size_t end) { body(begin, end); });
}

// A loop that stops at its first failure, over ranges: step(i) returns false for a failing i,
// each range stops at its own first one, and the result is the first failing i of the whole
// input (count when none). Every i before it has been stepped, as in the serial loop.
template <class Step>
std::size_t forEachUntilFirstFailure(std::size_t count, Step&& step) {
    std::vector<std::size_t> firstFailure(rangeCount(count), count);
    forEachRangeOf(count, firstFailure.size(),
                   [&](std::size_t range, std::size_t begin, std::size_t end) {
                       for (std::size_t i = begin; i < end; ++i) {
                           if (!step(i)) {
                               firstFailure[range] = i;
                               return;
                           }
                       }
                   });
    return *std::min_element(firstFailure.begin(), firstFailure.end());
}

// Runs first() and second(), two independent pieces of serial work over `work` points, at once
// on two threads when the context allows two and the work is worth a thread (at least
// kMinParallelRange points), otherwise one after the other on the calling thread. An exception
// in either is rethrown once both have ended, as in forEachRangeOf.
template <class First, class Second>
void runBoth(std::size_t work, First&& first, Second&& second) {
    if (currentThreadCount() < 2 || work < kMinParallelRange) {
        first();
        second();
        return;
    }
    forEachRangeOf(2, 2, [&](std::size_t range, std::size_t, std::size_t) {
        if (range == 0) {
            first();
        } else {
            second();
        }
    });
}

// Calls body(i) for every i in [0, count), items handed out one at a time to up to the context's
// thread count: for few items of uneven cost, such as the layers of a toolpath. `weight`
// is the total work in points; below kMinParallelRange points all of it runs serially.
template <class Body>
void forEachItem(std::size_t count, std::size_t weight, Body&& body) {
    const std::size_t workers = std::min(rangeCount(weight), count);
    std::atomic<std::size_t> next{0};
    forEachRangeOf(workers, workers, [&](std::size_t, std::size_t, std::size_t) {
        for (std::size_t i = next++; i < count; i = next++) {
            body(i);
        }
    });
}

} // namespace bladeaxis

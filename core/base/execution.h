#pragma once
// The execution context a thread runs under: how many threads the data-parallel loops of
// parallel.h may use. It is a property of the context, not a parameter of every function: the
// caller that knows (a job, from its `threads` setting; a test; a benchmark) sets it for a scope,
// and every library call made within that scope reads it. Without a scope a thread runs
// serially (1), so a library call is serial unless its caller's context says otherwise. The
// threads forEachRangeOf starts, and the tasks runAsync starts, run under their starter's count.

#include <algorithm>
#include <functional>
#include <future>
#include <thread>
#include <type_traits>
#include <utility>

namespace bladeaxis {

// The number of hardware threads, read once. libstdc++ asks the kernel on every call (it opens
// and reads /sys/devices/system/cpu/online), and a schedule asks about 25 times: on the demo's
// 3,000 points those reads were a fifth of the time.
inline unsigned hardwareThreadCount() {
    static const unsigned count = std::max(1u, std::thread::hardware_concurrency());
    return count;
}

// The thread count a `threads` setting means: 0 is every hardware thread.
inline unsigned resolveThreadCount(unsigned threads) {
    return threads != 0 ? threads : hardwareThreadCount();
}

namespace detail {
inline unsigned& contextThreadCount() {
    thread_local unsigned count = 1;
    return count;
}
} // namespace detail

// The number of threads (at least 1) the calling thread's context lets a parallel loop use.
inline unsigned currentThreadCount() {
    return detail::contextThreadCount();
}

// Sets the calling thread's thread count (0 = every hardware thread) until the scope ends,
// when the previous count is restored. Scopes nest.
class ThreadCountScope {
  public:
    explicit ThreadCountScope(unsigned threads) : m_previous(detail::contextThreadCount()) {
        detail::contextThreadCount() = resolveThreadCount(threads);
    }
    ~ThreadCountScope() { detail::contextThreadCount() = m_previous; }
    ThreadCountScope(const ThreadCountScope&) = delete;
    ThreadCountScope& operator=(const ThreadCountScope&) = delete;

  private:
    unsigned m_previous;
};

// Starts task() as std::async(policy, ...) would, under the starter's thread count wherever it
// runs: on a thread of its own (std::launch::async, the default), or later on the thread that
// waits for the future (std::launch::deferred).
template <class F>
auto runAsync(std::launch policy, F&& task) -> std::future<std::invoke_result_t<std::decay_t<F>&>> {
    return std::async(policy,
                      [threads = currentThreadCount(), task = std::forward<F>(task)]() mutable {
                          ThreadCountScope scope(threads);
                          return std::invoke(task);
                      });
}

template <class F>
auto runAsync(F&& task) -> std::future<std::invoke_result_t<std::decay_t<F>&>> {
    return runAsync(std::launch::async, std::forward<F>(task));
}

} // namespace bladeaxis

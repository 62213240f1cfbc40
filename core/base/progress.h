#pragma once
// Progress reporting and cooperative cancellation, free of any GUI toolkit. The GUI implements
// ProgressSink and marshals calls to its own thread; batch prints or ignores them.

#include "core/base/error.h"

#include <atomic>
#include <cstddef>
#include <string_view>

namespace bladeaxis {

// Set from any thread; long computations poll it between steps.
class CancelToken {
  public:
    void requestCancel() { m_cancelled.store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return m_cancelled.load(std::memory_order_relaxed); }

  private:
    std::atomic<bool> m_cancelled{false};
};

// Whether an optional token (null: the caller cannot cancel) is set.
inline bool isCancelled(const CancelToken* cancel) {
    return cancel != nullptr && cancel->isCancelled();
}

// The per-sample loops of large jobs look at their token every 65,536 iterations: a few
// milliseconds of any of them, and no cost worth measuring per iteration.
inline constexpr std::size_t kIterationsPerCancelPoll = std::size_t{1} << 16;

// Whether iteration i of such a loop should stop.
inline bool isCancelledAt(const CancelToken* cancel, std::size_t i) {
    return i % kIterationsPerCancelPoll == 0 && isCancelled(cancel);
}

// The one error of a computation stopped by its token, whichever stage it was in: every stage
// reports a cancellation with it, so that the callers (the batch front end, the GUI, the
// Python module) tell a cancellation by its code and never by a stage's wording.
inline Error cancelledError() {
    return Error{ErrorCode::Cancelled, "stopped on request", {}, {}};
}

// cancelledError() once an optional token (null: the caller cannot cancel) is set.
inline Status checkCancelled(const CancelToken* cancel) {
    if (isCancelled(cancel)) {
        return std::unexpected(cancelledError());
    }
    return {};
}
inline Status checkCancelled(const CancelToken& cancel) {
    return checkCancelled(&cancel);
}

class ProgressSink {
  public:
    virtual ~ProgressSink() = default;
    // fraction in [0, 1] of the whole job; stage names the running stage ("reading").
    virtual void progress(double fraction, std::string_view stage) = 0;
    // A warning about the input that does not stop the job.
    virtual void warning(std::string_view message) = 0;
};

// Discards everything; the default when a caller does not care.
class NullProgressSink final : public ProgressSink {
  public:
    void progress(double, std::string_view) override {}
    void warning(std::string_view) override {}
};

} // namespace bladeaxis

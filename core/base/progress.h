#pragma once
// Progress reporting and cooperative cancellation, free of any GUI toolkit. The GUI implements
// ProgressSink and marshals calls to its own thread; batch prints or ignores them.

#include <atomic>
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

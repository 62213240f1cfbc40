#pragma once
// The pages of large blocks mapped on a thread of its own while the calling thread goes on
// with serial work that will write them (the reader's records, a program's text).
//
// On a virtual machine the first touch of a fresh page is the largest single cost of a cold run:
// the guest zeroes it, and the host may have to find memory for it first. A serial stage that
// writes a large block from front to back pays that on its own core, page after page, while
// the other core waits. Here the second core maps the pages (Linux MADV_POPULATE_WRITE: as a
// write would, without writing), so the serial stage finds them mapped. The content is
// unchanged: a page already mapped is left as it is, and a fresh one reads as zeros either way.
//
// The thread maps a few megabytes at a time and stops at the next step when this object is
// destroyed. Mapping a block that was freed meanwhile is harmless: a range no longer mapped is
// refused, and one mapped again by another allocation only has its pages mapped sooner. Where
// the kernel cannot populate (before Linux 5.14, elsewhere than Linux), on one core, for blocks
// too small to be worth a thread, or when no thread can be started, this does nothing.

#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace bladeaxis {

struct MemoryRange {
    void* begin = nullptr;
    std::size_t bytes = 0;
};

class PagesMappedAhead {
  public:
    // Starts mapping the ranges in order, each from its start.
    explicit PagesMappedAhead(std::vector<MemoryRange> ranges);
    // Stops at the next step and waits for the thread.
    ~PagesMappedAhead();
    PagesMappedAhead(const PagesMappedAhead&) = delete;
    PagesMappedAhead& operator=(const PagesMappedAhead&) = delete;

    // Waits until every range is mapped (for tests and callers that need the whole block).
    void finish();

    // Whether a thread was started for these ranges.
    bool running() const { return m_thread.joinable(); }

  private:
    void mapAll();

    std::vector<MemoryRange> m_ranges;
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace bladeaxis

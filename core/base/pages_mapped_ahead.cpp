#include "core/base/pages_mapped_ahead.h"

#include "core/base/parallel.h"
#include "core/base/whole_pages.h"

#include <algorithm>
#include <cstdint>
#include <system_error>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bladeaxis {

namespace {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
constexpr bool kCanPopulate = true;
#else
constexpr bool kCanPopulate = false;
#endif

// Below this a thread's start costs more than the pages' mapping it moves.
constexpr std::size_t kSmallestMappedAhead = std::size_t{8} << 20;
// A step: two huge pages, or 1,024 small ones.
constexpr std::uintptr_t kStepBytes = std::uintptr_t{4} << 20;

// Maps the whole pages of [first, end); false when the kernel refuses (a kernel without
// MADV_POPULATE_WRITE, a range no longer mapped): the rest is left to the writer's first touch.
bool populate(std::uintptr_t first, std::uintptr_t end) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    return ::madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE) == 0;
#else
    (void)first;
    (void)end;
    return false;
#endif
}

} // namespace

PagesMappedAhead::PagesMappedAhead(std::vector<MemoryRange> ranges) : m_ranges(std::move(ranges)) {
    std::size_t total = 0;
    for (const MemoryRange& range : m_ranges) {
        total += range.bytes;
    }
    if (kCanPopulate && total >= kSmallestMappedAhead && hardwareThreadCount() >= 2) {
        try {
            m_thread = std::thread([this] { mapAll(); });
        } catch (const std::system_error&) {
            // No thread to be had (a process at its limit): the writer maps its pages itself.
        }
    }
}

PagesMappedAhead::~PagesMappedAhead() {
    m_stop.store(true, std::memory_order_relaxed);
    finish();
}

void PagesMappedAhead::finish() {
    if (m_thread.joinable()) {
        m_thread.join();
    }
}

void PagesMappedAhead::mapAll() {
    for (const MemoryRange& range : m_ranges) {
        const PageRange pages = wholePagesIn(range.begin, range.bytes);
        for (std::uintptr_t at = pages.first; at < pages.end; at += kStepBytes) {
            if (m_stop.load(std::memory_order_relaxed) ||
                !populate(at, std::min(pages.end, at + kStepBytes))) {
                return;
            }
        }
    }
}

} // namespace bladeaxis

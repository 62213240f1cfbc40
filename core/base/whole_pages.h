#pragma once
// The whole pages inside a block of memory: what the calls that advise, map or give back pages
// (madvise) act on. The partial pages at either end are left to the block's neighbours.

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <unistd.h>
#endif

namespace bladeaxis {

inline std::uintptr_t pageBytes() {
#if defined(__linux__)
    static const auto bytes = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    return bytes;
#else
    return 4096;
#endif
}

// [first, end), empty when first >= end.
struct PageRange {
    std::uintptr_t first = 0, end = 0;
};

inline PageRange wholePagesIn(const void* block, std::size_t bytes) {
    const std::uintptr_t page = pageBytes();
    const auto begin = reinterpret_cast<std::uintptr_t>(block);
    return {(begin + page - 1) & ~(page - 1), (begin + bytes) & ~(page - 1)};
}

} // namespace bladeaxis

#include "core/base/memory_policy.h"

#include <atomic>
#include <cstdint>
#include <cstdlib> // defines __GLIBC__ where the C library is glibc
#include <new>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace bladeaxis {

namespace {

std::atomic<bool> adviseHugePages{false};

constexpr std::size_t kAdviseFromBytes = std::size_t{4} << 20;

std::uintptr_t pageBytes() {
#if defined(__linux__)
    static const auto bytes = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    return bytes;
#else
    return 4096;
#endif
}

// The whole pages inside [block, block + bytes): [first, end), empty when first >= end.
struct PageRange {
    std::uintptr_t first = 0, end = 0;
};
PageRange wholePagesIn(void* block, std::size_t bytes) {
    const std::uintptr_t page = pageBytes();
    const auto begin = reinterpret_cast<std::uintptr_t>(block);
    return {(begin + page - 1) & ~(page - 1), (begin + bytes) & ~(page - 1)};
}

#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(__SANITIZE_ADDRESS__)
#define BLADEAXIS_REPLACES_NEW 1

// Marks the whole pages inside the block. With blocks of 1 MB or more mapped on their own
// (returnLargeBlocksToTheSystem), they are still untouched here, so the first touch of each
// aligned 2 MiB stretch maps one huge page instead of 512 small ones. The advice is a hint:
// a refusal (EINVAL where THP is compiled out) changes nothing but speed.
void adviseHugePagesFor(void* block, std::size_t bytes) {
    const PageRange pages = wholePagesIn(block, bytes);
    if (pages.end > pages.first) {
        ::madvise(reinterpret_cast<void*>(pages.first), pages.end - pages.first, MADV_HUGEPAGE);
    }
}
#endif

} // namespace

void returnLargeBlocksToTheSystem() {
#if defined(__GLIBC__)
    constexpr int kMapBlocksFromBytes = 1 << 20;
    mallopt(M_MMAP_THRESHOLD, kMapBlocksFromBytes);
#endif
}

void backLargeBlocksWithHugePages() {
#if defined(BLADEAXIS_REPLACES_NEW)
    adviseHugePages.store(true, std::memory_order_relaxed);
#endif
}

bool largeBlocksAreAdvisedHugePages() {
    return adviseHugePages.load(std::memory_order_relaxed);
}

void returnFreedHeapToTheSystem() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

std::size_t returnWholePagesToTheSystem(void* begin, std::size_t bytes) {
#if defined(__linux__)
    const PageRange pages = wholePagesIn(begin, bytes);
    if (pages.end <= pages.first) {
        return 0;
    }
    // Advice on memory this process owns cannot fail but for a kernel without it; the pages
    // then stay resident until the block is freed, as without the call.
    ::madvise(reinterpret_cast<void*>(pages.first), pages.end - pages.first, MADV_DONTNEED);
    return pages.end - reinterpret_cast<std::uintptr_t>(begin);
#else
    (void)begin;
    (void)bytes;
    return 0;
#endif
}

} // namespace bladeaxis

#if defined(BLADEAXIS_REPLACES_NEW)
// The replaceable global allocation function (the standard's [new.delete.single]): the
// library's own does the same loop over malloc and the new-handler. The other forms (arrays,
// nothrow) call this one in libstdc++; every delete frees with free(), which these blocks
// came from.
void* operator new(std::size_t bytes) {
    const std::size_t asked = bytes == 0 ? 1 : bytes;
    for (;;) {
        if (void* block = std::malloc(asked)) {
            if (asked >= bladeaxis::kAdviseFromBytes &&
                bladeaxis::adviseHugePages.load(std::memory_order_relaxed)) {
                bladeaxis::adviseHugePagesFor(block, asked);
            }
            return block;
        }
        const std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) {
            throw std::bad_alloc();
        }
        handler();
    }
}
#endif

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
#endif

namespace bladeaxis {

namespace {

std::atomic<bool> adviseHugePages{false};

constexpr std::size_t kAdviseFromBytes = std::size_t{4} << 20;

#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(__SANITIZE_ADDRESS__)
#define BLADEAXIS_REPLACES_NEW 1

constexpr std::uintptr_t kPageBytes = 4096;

// Marks the whole pages inside the block. With blocks of 1 MB or more mapped on their own
// (returnLargeBlocksToTheSystem), they are still untouched here, so the first touch of each
// aligned 2 MiB stretch maps one huge page instead of 512 small ones. The advice is a hint:
// a refusal (EINVAL where THP is compiled out) changes nothing but speed.
void adviseHugePagesFor(void* block, std::size_t bytes) {
    const auto begin =
        (reinterpret_cast<std::uintptr_t>(block) + kPageBytes - 1) & ~(kPageBytes - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(block) + bytes) & ~(kPageBytes - 1);
    if (end > begin) {
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
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

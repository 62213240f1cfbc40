#include "core/base/memory_policy.h"

#include "core/base/large_block_shelf.h"
#include "core/base/whole_pages.h"

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
std::atomic<bool> keepFreedLargeBlocks{false};
constinit LargeBlockShelf shelf;

constexpr std::size_t kAdviseFromBytes = std::size_t{4} << 20;

#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE) &&                          \
    !defined(__SANITIZE_ADDRESS__)
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

void keepFreedLargeBlocksForReuse() {
#if defined(BLADEAXIS_REPLACES_NEW)
    keepFreedLargeBlocks.store(true, std::memory_order_relaxed);
#endif
}

void countMappedFileBytes(std::size_t bytes) {
    if (keepFreedLargeBlocks.load(std::memory_order_relaxed)) {
        shelf.noteInUse(bytes);
    }
}

void uncountMappedFileBytes(std::size_t bytes) {
    if (keepFreedLargeBlocks.load(std::memory_order_relaxed)) {
        shelf.noteGone(bytes);
    }
}

void stopKeepingFreedLargeBlocks() {
    keepFreedLargeBlocks.store(false, std::memory_order_relaxed);
    shelf.freeAll();
}

std::size_t keptLargeBlockBytes() {
    return shelf.keptBytes();
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
namespace {

bool keepsLargeBlocks() {
    return bladeaxis::keepFreedLargeBlocks.load(std::memory_order_relaxed);
}

// Small blocks reach the shelf's count in batches of about a megabyte per thread: a lock per
// allocation would cost more than the allocation. The count is off by at most a batch per
// thread.
constexpr std::ptrdiff_t kReportSmallBlocksEvery = std::ptrdiff_t{1} << 20;
thread_local std::ptrdiff_t unreportedSmallBytes = 0;

void countSmallBlock(std::ptrdiff_t bytes) {
    unreportedSmallBytes += bytes;
    if (unreportedSmallBytes >= kReportSmallBlocksEvery) {
        bladeaxis::shelf.noteInUse(static_cast<std::size_t>(unreportedSmallBytes));
        unreportedSmallBytes = 0;
    } else if (unreportedSmallBytes <= -kReportSmallBlocksEvery) {
        bladeaxis::shelf.noteGone(static_cast<std::size_t>(-unreportedSmallBytes));
        unreportedSmallBytes = 0;
    }
}

void* takeKept(std::size_t bytes) {
    if (bytes >= bladeaxis::LargeBlockShelf::kSmallestKeptBytes && keepsLargeBlocks()) {
        return bladeaxis::shelf.take(bytes);
    }
    return nullptr;
}

void countAllocated(void* block) {
    if (!keepsLargeBlocks()) {
        return;
    }
    const std::size_t usable = malloc_usable_size(block);
    if (usable >= bladeaxis::LargeBlockShelf::kSmallestKeptBytes) {
        bladeaxis::shelf.noteInUse(usable);
    } else {
        countSmallBlock(static_cast<std::ptrdiff_t>(usable));
    }
}

void freeOrKeep(void* block) {
    if (block != nullptr && keepsLargeBlocks()) {
        const std::size_t usable = malloc_usable_size(block);
        if (usable < bladeaxis::LargeBlockShelf::kSmallestKeptBytes) {
            countSmallBlock(-static_cast<std::ptrdiff_t>(usable));
        } else if (bladeaxis::shelf.keep(block, usable)) {
            return;
        }
    }
    std::free(block);
}

} // namespace

// The replaceable global allocation function (the standard's [new.delete.single]): the
// library's own does the same loop over malloc and the new-handler. The other forms (arrays,
// nothrow) call this one in libstdc++, and its other deallocation forms call the two below;
// the aligned forms use their own functions and never meet the shelf.
void* operator new(std::size_t bytes) {
    const std::size_t asked = bytes == 0 ? 1 : bytes;
    if (void* kept = takeKept(asked)) {
        return kept;
    }
    for (;;) {
        if (void* block = std::malloc(asked)) {
            if (asked >= bladeaxis::kAdviseFromBytes &&
                bladeaxis::adviseHugePages.load(std::memory_order_relaxed)) {
                bladeaxis::adviseHugePagesFor(block, asked);
            }
            countAllocated(block);
            return block;
        }
        const std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) {
            throw std::bad_alloc();
        }
        handler();
    }
}

// Both forms look at the block's own size: a block taken from the shelf may be a little larger
// than the size asked for, which is what the sized form is given.
void operator delete(void* block) noexcept {
    freeOrKeep(block);
}

void operator delete(void* block, std::size_t) noexcept {
    freeOrKeep(block);
}
#endif

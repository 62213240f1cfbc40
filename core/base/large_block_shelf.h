#pragma once
// Freed large blocks kept, mapped and resident, for the next request of about their size.
//
// A job allocates and frees its per-record arrays (tens of megabytes each at five million
// records) one stage after another: about 3.9 GB of fresh blocks for a peak of 1.4 GB. Each
// fresh block's pages are zeroed by the kernel on first touch, which is the largest single cost
// of such a job on a virtual machine (a third of its CPU time). A block kept here is handed out
// again with its pages already mapped.
//
// The shelf never makes the process larger than its peak: the bytes in use plus the bytes kept
// never exceed the most that were in use at once. "In use" is every block the program holds,
// small ones too (a job's layers hold hundreds of megabytes in small blocks while its large
// arrays are freed), and a file mapped for reading; the caller reports them (noteInUse,
// noteGone), small blocks in batches. Keeping a freed block moves its bytes from in use to
// kept, which leaves the sum as it was; memory newly in use that raises the sum above the bound
// makes the shelf free kept blocks (the largest first) until the bound holds again. A block
// freed when every place is taken goes back to the C library.
//
// The blocks are the C library's (malloc); the shelf frees them with free(). It is thread-safe.
// Its state is constant-initialised, so it may serve allocations made before main.

#include <array>
#include <cstddef>
#include <mutex>

namespace bladeaxis {

class LargeBlockShelf {
  public:
    // Blocks smaller than this are not kept: the C library serves them well enough.
    static constexpr std::size_t kSmallestKeptBytes = std::size_t{4} << 20;
    // A job's stage frees at most a few dozen per-record arrays before the next stage asks for
    // arrays of the same sizes; beyond that, blocks go back to the C library.
    static constexpr std::size_t kPlaces = 32;

    constexpr LargeBlockShelf() = default;

    // A kept block of at least `bytes` and at most 1/32 more, the smallest such, now in use;
    // nullptr when none fits. The arrays of one job are of a few sizes (records times 8, 24,
    // 40 bytes); a much larger block would hold resident pages the request never uses.
    void* take(std::size_t bytes);

    // Records memory newly in use (blocks obtained from the C library, a file mapped for
    // reading), and frees kept blocks if the bound needs it.
    void noteInUse(std::size_t bytes);

    // Records that memory counted by noteInUse, not handed to keep(), is no longer in use. The
    // count may go below zero for a while: one thread frees what another allocated, and each
    // reports in its own batches.
    void noteGone(std::size_t bytes);

    // Keeps a block being freed, of `usableBytes` (malloc_usable_size), or returns false (every
    // place taken) and the caller frees it.
    bool keep(void* block, std::size_t usableBytes);

    // Frees every kept block.
    void freeAll();

    std::size_t keptBytes() const;
    std::ptrdiff_t bytesInUse() const;
    std::ptrdiff_t mostBytesInUse() const;

  private:
    struct Place {
        void* block = nullptr;
        std::size_t bytes = 0;
    };

    void freeLargestUntilWithinBound();

    mutable std::mutex mutex_;
    std::array<Place, kPlaces> places_{};
    std::size_t kept_ = 0;
    std::ptrdiff_t inUse_ = 0;
    std::ptrdiff_t mostInUse_ = 0;
};

} // namespace bladeaxis

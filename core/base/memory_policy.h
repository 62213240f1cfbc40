#pragma once
// How the process maps and hands back large blocks. Called once by a program's main (the
// application, the benchmarks), never by the libraries: each sets a process-wide policy.

#include <cstddef>

namespace bladeaxis {

// The C library (glibc) serves a freed block of up to 32 MB again from its heap the next time,
// and raises its threshold for mapping blocks to the largest block freed so far. A job's
// per-record arrays are megabytes each; freed into the heap, they stay resident beside the
// arrays that follow, and a million-block job's peak resident memory is about 100 MB above what
// it holds at any moment. A fixed threshold of 1 MB maps every larger block on its own and
// unmaps it when freed: the resident peak is then what the job holds, at no measurable cost in
// time (the first touch of fresh pages is paid either way by arrays of that size).
// Elsewhere than glibc this does nothing.
void returnLargeBlocksToTheSystem();

// Asks the kernel to back every block of 4 MB or more allocated with `new` (the per-record
// arrays and texts of a job) with transparent huge pages. Linux's default THP mode
// ("madvise") gives them only to memory that asks for them. A large job's time is dominated by
// the first touch of fresh memory: with 4 KiB pages a five-million-block job takes about
// 1.5 million page faults and spends more time in the kernel than in its own arithmetic; with
// 2 MiB pages it takes about 0.1 million. The resident peak grows by at most the unused part
// of a block's last huge page. Where the kernel has no huge pages, or THP is off, or in an
// address-sanitizer build (whose allocator serves `new`), this does nothing.
void backLargeBlocksWithHugePages();

// Keeps blocks of 4 MB or more, once freed, for the next request of about their size, instead
// of handing them back to the system (LargeBlockShelf): a job's stages free and allocate
// per-record arrays of the same sizes one after another, and a kept block is served again
// without the kernel zeroing its pages. What is kept never makes the process larger than the
// most it held in large blocks at once. For a program that runs one job and ends (the batch
// front end); a program that stays (the GUI) would keep that memory while idle. Where the
// application does not replace `new` (an address-sanitizer build, other C libraries), this
// does nothing.
void keepFreedLargeBlocksForReuse();

// A file's pages mapped for reading join the resident set as they are read: `bytes` of them
// count as in use for the bound of the kept blocks until given back here (MappedText does
// both). Without the policy in force this does nothing.
void countMappedFileBytes(std::size_t bytes);
void uncountMappedFileBytes(std::size_t bytes);

// Stops keeping freed large blocks and frees those kept.
void stopKeepingFreedLargeBlocks();

// The bytes of the blocks kept now (for tests and benchmarks).
std::size_t keptLargeBlockBytes();

// Whether backLargeBlocksWithHugePages() is in force in this process (for tests).
bool largeBlocksAreAdvisedHugePages();

// Gives back to the system the free memory the C library keeps for later allocations: glibc
// keeps a job's small blocks (a layer's arrays, a few kilobytes each), once freed, in its
// per-thread arenas, and the next job in the same process starts above what a fresh process
// holds (a million-block read-schedule-write: 408 MiB for the first job, up to 432 MiB for the
// third). For a program that runs one job after another: the GUI before each job, a benchmark
// before each iteration. Elsewhere than glibc this does nothing.
void returnFreedHeapToTheSystem();

// Gives the whole pages inside [begin, begin + bytes) of a block back to the system now, while
// the block stays allocated: for the front of a large array its owner has read for the last
// time but frees only as a whole, later. Those pages read as zeros afterwards (Linux
// MADV_DONTNEED on private memory; a shared file mapping reads them again from its file); the
// partial pages at either end keep their bytes. Returns how far from `begin` the pages given
// back reach (0 when none, and elsewhere than Linux, where this does nothing).
std::size_t returnWholePagesToTheSystem(void* begin, std::size_t bytes);

} // namespace bladeaxis

#pragma once
// Memory the core gives back to the system on its own account. No allocator policy: the core's
// libraries are linked into plug-ins and the Python module, whose host owns the allocator and
// its settings. The executable's policy (mapping threshold, huge pages) is app/memory's.

#include <cstddef>

namespace bladeaxis {

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

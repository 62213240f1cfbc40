#pragma once
// The executable's memory policy: process-wide settings of the C library's allocator, made once
// by main (the application, the job benchmarks). Here and not in a core library: the core is
// linked into plug-ins and the Python module, whose host owns the allocator and its settings.
// docs/performance.md, "Memory policy of the executable", has what each setting is measured to
// give.

namespace bladeaxis::app {

// The C library (glibc) serves a freed block of up to 32 MB again from its heap the next time,
// and raises its threshold for mapping blocks to the largest block freed so far. A job's
// per-record arrays are megabytes each; freed into the heap, they stay resident beside the
// arrays that follow. A fixed threshold of 1 MB maps every larger block on its own and unmaps
// it when freed, so the resident peak is what the job holds. Elsewhere than glibc this does
// nothing.
void returnLargeBlocksToTheSystem();

} // namespace bladeaxis::app

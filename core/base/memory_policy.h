#pragma once
// How the process hands large freed blocks back to the system. Called once by a program's main
// (the application, the benchmarks), never by the libraries: it sets a process-wide policy.

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

} // namespace bladeaxis

#pragma once
// The process's resident memory, for the tests of what gives memory back to the system.

#include <cstddef>
#include <fstream>
#include <unistd.h>

namespace bladeaxis::test {

// The process's resident set in bytes (/proc/self/statm: size, resident, ... in pages).
inline std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

// An address-sanitizer build serves memory from its own allocator, which ignores the C
// library's settings and keeps freed blocks in quarantine.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizerAllocator = true;
#else
inline constexpr bool kSanitizerAllocator = false;
#endif

} // namespace bladeaxis::test

#include "core/base/memory_policy.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <unistd.h>

namespace bladeaxis {
namespace {

// The process's resident set in bytes (/proc/self/statm: size, resident, ... in pages).
std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

// A block of `bytes`, every page written, then freed.
void touchAndFree(std::size_t bytes) {
    const auto block = std::make_unique<char[]>(bytes);
    for (std::size_t i = 0; i < bytes; i += 4096) {
        block[i] = static_cast<char>(i);
    }
    volatile char sink = block[bytes / 2];
    (void)sink;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kOwnAllocator = true; // the sanitizer's allocator ignores the C library's settings
#else
constexpr bool kOwnAllocator = false;
#endif

// Without the policy glibc serves the 8 MB block from its heap after a 16 MB block was freed
// (its mapping threshold rises to 16 MB), and the freed 8 MB stay resident.
TEST(MemoryPolicy, AFreedLargeArrayNoLongerCountsAsResident) {
    if (kOwnAllocator) {
        GTEST_SKIP() << "an address-sanitizer build has its own allocator";
    }
    returnLargeBlocksToTheSystem();
    touchAndFree(16u << 20);
    const std::size_t before = residentBytes();
    touchAndFree(8u << 20);
    const std::size_t after = residentBytes();
    EXPECT_LT(after, before + (2u << 20)) << "resident before " << before << ", after " << after;
}

} // namespace
} // namespace bladeaxis

#include "app/memory/memory_policy.h"
#include "tests/support/resident_memory.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>

namespace bladeaxis::app {
namespace {

using test::kSanitizerAllocator;
using test::residentBytes;

// A block of `bytes`, every page written, then freed.
void touchAndFree(std::size_t bytes) {
    const auto block = std::make_unique<char[]>(bytes);
    for (std::size_t i = 0; i < bytes; i += 4096) {
        block[i] = static_cast<char>(i);
    }
    volatile char sink = block[bytes / 2];
    (void)sink;
}

// Without the policy glibc serves the 8 MB block from its heap after a 16 MB block was freed
// (its mapping threshold rises to 16 MB), and the freed 8 MB stay resident.
TEST(ExecutableMemoryPolicy, AFreedLargeArrayNoLongerCountsAsResident) {
    if (kSanitizerAllocator) {
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
} // namespace bladeaxis::app

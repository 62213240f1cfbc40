#include "core/base/memory_policy.h"
#include "tests/support/resident_memory.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

namespace bladeaxis {
namespace {

using test::kSanitizerAllocator;
using test::residentBytes;

// 64 MB of small blocks (below the mapping threshold: from the heap) are written and freed
// but for the last, which keeps the heap's top from shrinking by itself: glibc keeps the rest,
// resident, for later allocations until it is asked to give it back.
TEST(MemoryPolicy, FreedSmallBlocksLeaveTheResidentSetWhenTheHeapIsGivenBack) {
    if (kSanitizerAllocator) {
        GTEST_SKIP() << "an address-sanitizer build has its own allocator";
    }
    constexpr std::size_t kBlock = 4096;
    constexpr std::size_t kBlocks = (64u << 20) / kBlock;
    std::vector<std::unique_ptr<char[]>> blocks(kBlocks);
    for (auto& block : blocks) {
        block = std::make_unique<char[]>(kBlock);
        block[kBlock / 2] = 1;
    }
    const auto top = std::make_unique<char[]>(kBlock);
    for (auto& block : blocks) {
        block.reset();
    }
    const std::size_t freed = residentBytes();
    returnFreedHeapToTheSystem();
    const std::size_t givenBack = residentBytes();
    EXPECT_LT(givenBack + (48u << 20), freed)
        << "resident after the frees " << freed << ", after giving the heap back " << givenBack;
}

// Whether each page of [begin, begin + bytes) is resident (mincore), begin page-aligned.
std::vector<bool> residentPages(const char* begin, std::size_t bytes) {
    const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> flags((bytes + page - 1) / page);
    if (::mincore(const_cast<char*>(begin), bytes, flags.data()) != 0) {
        return {};
    }
    std::vector<bool> resident;
    for (unsigned char flag : flags) {
        resident.push_back((flag & 1u) != 0);
    }
    return resident;
}

TEST(MemoryPolicy, ReturnedPagesLeaveTheResidentSetAndThePartialPagesKeepTheirBytes) {
    const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    const std::size_t bytes = 64 * page;
    auto* block = static_cast<char*>(std::aligned_alloc(page, bytes));
    ASSERT_NE(block, nullptr);
    for (std::size_t i = 0; i < bytes; ++i) {
        block[i] = static_cast<char>(1 + i % 251);
    }
    // From the middle of page 2 to the middle of page 40: pages 3..39 are whole.
    const std::size_t from = 2 * page + page / 2;
    const std::size_t to = 40 * page + page / 2;
    returnWholePagesToTheSystem(block + from, to - from);
    const std::vector<bool> resident = residentPages(block, bytes);
    ASSERT_EQ(resident.size(), 64u);
    for (std::size_t p = 0; p < 64; ++p) {
        EXPECT_EQ(resident[p], p < 3 || p >= 40) << "page " << p;
    }
    for (std::size_t i = 0; i < bytes; ++i) {
        const bool returned = i >= 3 * page && i < 40 * page;
        ASSERT_EQ(block[i], returned ? 0 : static_cast<char>(1 + i % 251)) << i;
    }
    std::free(block);
}

} // namespace
} // namespace bladeaxis

#include "core/base/file_io.h"
#include "core/base/memory_policy.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

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

// 64 MB of small blocks (below the mapping threshold: from the heap) are written and freed
// but for the last, which keeps the heap's top from shrinking by itself: glibc keeps the rest,
// resident, for later allocations until it is asked to give it back.
TEST(MemoryPolicy, FreedSmallBlocksLeaveTheResidentSetWhenTheHeapIsGivenBack) {
    if (kOwnAllocator) {
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

// The VmFlags line of the mapping that holds `address` in /proc/self/smaps ("" if none). The
// kernel marks a range advised MADV_HUGEPAGE with the flag "hg", whether or not huge pages
// were free to back it, so the advice is seen without depending on the host's memory.
std::string mappingFlagsOf(const void* address) {
    const auto where = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t begin = 0, end = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> begin >> dash >> end && dash == '-') {
            inside = begin <= where && where < end;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line;
        }
    }
    return {};
}

bool hasFlag(const std::string& flags, const std::string& flag) {
    return (flags + " ").find(" " + flag + " ") != std::string::npos;
}

bool kernelHasTransparentHugePages() {
    return std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled");
}

TEST(MemoryPolicy, ALargeBlockAsksForHugePagesAndASmallerOneDoesNot) {
    if (kOwnAllocator || !kernelHasTransparentHugePages()) {
        GTEST_SKIP() << "no transparent huge pages here, or the sanitizer's allocator serves new";
    }
    returnLargeBlocksToTheSystem(); // each block of 1 MB or more on a mapping of its own
    backLargeBlocksWithHugePages();
    ASSERT_TRUE(largeBlocksAreAdvisedHugePages());
    const std::size_t large = 16u << 20;
    const std::size_t small = 2u << 20;
    const auto largeBlock = std::make_unique<char[]>(large);
    const auto smallBlock = std::make_unique<char[]>(small);
    const std::string largeFlags = mappingFlagsOf(largeBlock.get() + large / 2);
    const std::string smallFlags = mappingFlagsOf(smallBlock.get() + small / 2);
    ASSERT_FALSE(largeFlags.empty());
    ASSERT_FALSE(smallFlags.empty());
    EXPECT_TRUE(hasFlag(largeFlags, "hg")) << largeFlags;
    EXPECT_FALSE(hasFlag(smallFlags, "hg")) << smallFlags;
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

// The address of a block value-initialised (so written) and freed: a number, as a freed
// pointer may not be read.
std::uintptr_t touchedThenFreed(std::size_t bytes) {
    auto block = std::make_unique<char[]>(bytes);
    const auto address = reinterpret_cast<std::uintptr_t>(block.get());
    block.reset();
    return address;
}

TEST(MemoryPolicy, AFreedLargeBlockIsServedAgainToTheNextRequestOfItsSize) {
    if (kOwnAllocator) {
        GTEST_SKIP() << "an address-sanitizer build has its own allocator";
    }
    returnLargeBlocksToTheSystem();
    keepFreedLargeBlocksForReuse();
    constexpr std::size_t kBytes = 16u << 20;
    const std::uintptr_t freed = touchedThenFreed(kBytes);
    EXPECT_GE(keptLargeBlockBytes(), kBytes);
    const auto again = std::make_unique<char[]>(kBytes);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(again.get()), freed);
    EXPECT_EQ(again[kBytes / 2], 0) << "value-initialised like any new block";
    EXPECT_EQ(keptLargeBlockBytes(), 0u);
    stopKeepingFreedLargeBlocks();
}

// The 32 MiB block was the most the process held; with it kept, 8 MiB of small blocks would
// make the process larger than that, so the kept block goes back to the system.
TEST(MemoryPolicy, SmallBlocksInUseMakeKeptBlocksGoRatherThanThePeakGrow) {
    if (kOwnAllocator) {
        GTEST_SKIP() << "an address-sanitizer build has its own allocator";
    }
    returnLargeBlocksToTheSystem();
    keepFreedLargeBlocksForReuse();
    touchedThenFreed(32u << 20);
    ASSERT_GE(keptLargeBlockBytes(), 32u << 20);
    constexpr std::size_t kSmall = 4096;
    std::vector<std::unique_ptr<char[]>> small((8u << 20) / kSmall);
    for (auto& block : small) {
        block = std::make_unique<char[]>(kSmall);
    }
    EXPECT_EQ(keptLargeBlockBytes(), 0u);
    stopKeepingFreedLargeBlocks();
}

// A file mapped for reading grows the resident set as it is read, like a block in use.
TEST(MemoryPolicy, AMappedFileMakesKeptBlocksGoRatherThanThePeakGrow) {
    if (kOwnAllocator) {
        GTEST_SKIP() << "an address-sanitizer build has its own allocator";
    }
    const auto path = std::filesystem::temp_directory_path() /
                      ("bladeaxis_mapped_" + std::to_string(::getpid()) + ".txt");
    auto staged = StagedFile::open(path);
    ASSERT_TRUE(staged) << staged.error().message;
    ASSERT_TRUE(staged->append(std::string(8u << 20, 'x')));
    returnLargeBlocksToTheSystem();
    keepFreedLargeBlocksForReuse();
    touchedThenFreed(32u << 20);
    ASSERT_GE(keptLargeBlockBytes(), 32u << 20);
    {
        auto mapped = staged->mapText();
        ASSERT_TRUE(mapped) << mapped.error().message;
        EXPECT_EQ(keptLargeBlockBytes(), 0u);
    }
    stopKeepingFreedLargeBlocks();
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

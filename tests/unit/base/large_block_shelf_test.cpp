#include "core/base/large_block_shelf.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <vector>

namespace bladeaxis {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

// Blocks from the C library, never touched (so they cost no resident memory), counted in use as
// the allocation function counts them. The shelf frees those it gives back; a test frees the
// rest when it ends.
class ShelfTest : public ::testing::Test {
  protected:
    void* fresh(std::size_t bytes) {
        void* block = std::malloc(bytes);
        shelf.noteInUse(bytes);
        return block;
    }

    // In use plus kept never above the most in use.
    void expectWithinPeak() const {
        EXPECT_LE(shelf.bytesInUse() + static_cast<std::ptrdiff_t>(shelf.keptBytes()),
                  shelf.mostBytesInUse());
    }

    LargeBlockShelf shelf;
};

TEST_F(ShelfTest, AKeptBlockIsHandedOutAgainForARequestOfItsSize) {
    void* block = fresh(16 * kMiB);
    ASSERT_TRUE(shelf.keep(block, 16 * kMiB));
    EXPECT_EQ(shelf.keptBytes(), 16 * kMiB);
    EXPECT_EQ(shelf.bytesInUse(), 0);

    EXPECT_EQ(shelf.take(16 * kMiB), block);
    EXPECT_EQ(shelf.keptBytes(), 0u);
    EXPECT_EQ(shelf.bytesInUse(), static_cast<std::ptrdiff_t>(16 * kMiB));
    std::free(block);
}

// A request up to 1/32 smaller than a kept block gets it; a larger request, or a much smaller
// one (whose unused pages would stay resident), does not.
TEST_F(ShelfTest, AKeptBlockServesOnlyRequestsANearSizeAtMostItsOwn) {
    void* block = fresh(32 * kMiB);
    ASSERT_TRUE(shelf.keep(block, 32 * kMiB));
    EXPECT_EQ(shelf.take(32 * kMiB + 1), nullptr);
    EXPECT_EQ(shelf.take(31 * kMiB), nullptr);
    EXPECT_EQ(shelf.take(31 * kMiB + kMiB / 2), block);
    std::free(block);
}

TEST_F(ShelfTest, TheSmallestFittingBlockIsHandedOut) {
    void* larger = fresh(16 * kMiB + kMiB / 4);
    void* smaller = fresh(16 * kMiB);
    ASSERT_TRUE(shelf.keep(larger, 16 * kMiB + kMiB / 4));
    ASSERT_TRUE(shelf.keep(smaller, 16 * kMiB));
    EXPECT_EQ(shelf.take(16 * kMiB), smaller);
    EXPECT_EQ(shelf.take(16 * kMiB), larger);
    std::free(smaller);
    std::free(larger);
}

// The peak was 16 MiB (two blocks of 8); with one of them kept, 4 MiB more in use would make
// 20 MiB, so the kept block goes back.
TEST_F(ShelfTest, MemoryNewlyInUseFreesKeptBlocksThatWouldPassThePeak) {
    void* first = fresh(8 * kMiB);
    void* second = fresh(8 * kMiB);
    ASSERT_TRUE(shelf.keep(first, 8 * kMiB));
    expectWithinPeak();
    shelf.noteInUse(4 * kMiB);
    EXPECT_EQ(shelf.keptBytes(), 0u);
    expectWithinPeak();
    std::free(second);
}

TEST_F(ShelfTest, TheLargestKeptBlocksGoFirstAndOnlyAsManyAsTheBoundNeeds) {
    void* small = fresh(8 * kMiB);
    void* large = fresh(16 * kMiB);
    void* staying = fresh(8 * kMiB);
    ASSERT_TRUE(shelf.keep(small, 8 * kMiB));
    ASSERT_TRUE(shelf.keep(large, 16 * kMiB));
    // 8 in use, 24 kept, peak 32: 10 more in use need 10 back, which the 16 MiB block gives.
    shelf.noteInUse(10 * kMiB);
    EXPECT_EQ(shelf.keptBytes(), 8 * kMiB);
    EXPECT_EQ(shelf.take(8 * kMiB), small);
    expectWithinPeak();
    std::free(small);
    std::free(staying);
}

// Memory gone from use (small blocks freed, a mapping's pages given back) makes room for kept
// blocks without raising the peak.
TEST_F(ShelfTest, MemoryGoneFromUseLeavesRoomForKeptBlocks) {
    void* block = fresh(8 * kMiB);
    shelf.noteInUse(8 * kMiB); // small blocks
    shelf.noteGone(8 * kMiB);
    ASSERT_TRUE(shelf.keep(block, 8 * kMiB));
    shelf.noteInUse(8 * kMiB);
    EXPECT_EQ(shelf.keptBytes(), 8 * kMiB) << "8 in use and 8 kept are the peak of 16";
    expectWithinPeak();
    shelf.freeAll();
}

TEST_F(ShelfTest, ABlockFreedWhenEveryPlaceIsTakenIsNotKept) {
    std::vector<void*> blocks;
    for (std::size_t i = 0; i <= LargeBlockShelf::kPlaces; ++i) {
        blocks.push_back(fresh(LargeBlockShelf::kSmallestKeptBytes));
    }
    for (std::size_t i = 0; i < LargeBlockShelf::kPlaces; ++i) {
        ASSERT_TRUE(shelf.keep(blocks[i], LargeBlockShelf::kSmallestKeptBytes)) << i;
    }
    EXPECT_FALSE(shelf.keep(blocks.back(), LargeBlockShelf::kSmallestKeptBytes));
    std::free(blocks.back());
    shelf.freeAll();
    EXPECT_EQ(shelf.keptBytes(), 0u);
}

} // namespace
} // namespace bladeaxis

#include "core/base/pages_mapped_ahead.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

namespace bladeaxis {
namespace {

std::size_t pageBytes() {
    return static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

// A fresh anonymous mapping, unmapped when the test ends; no page of it is resident yet.
class FreshMapping {
  public:
    explicit FreshMapping(std::size_t bytes) : m_bytes(bytes) {
        void* data = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                            MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        m_data = data == MAP_FAILED ? nullptr : static_cast<char*>(data);
    }
    ~FreshMapping() {
        if (m_data != nullptr) {
            ::munmap(m_data, m_bytes);
        }
    }
    FreshMapping(const FreshMapping&) = delete;
    FreshMapping& operator=(const FreshMapping&) = delete;

    char* data() const { return m_data; }
    std::size_t bytes() const { return m_bytes; }

    // How many of its pages are resident (mincore).
    std::size_t residentPages() const {
        std::vector<unsigned char> flags(m_bytes / pageBytes());
        if (::mincore(m_data, m_bytes, flags.data()) != 0) {
            return 0;
        }
        std::size_t resident = 0;
        for (unsigned char flag : flags) {
            resident += flag & 1u;
        }
        return resident;
    }

  private:
    char* m_data = nullptr;
    std::size_t m_bytes = 0;
};

TEST(PagesMappedAhead, MapsEveryPageOfItsRangesAndLeavesTheirBytes) {
    FreshMapping block(16u << 20);
    ASSERT_NE(block.data(), nullptr);
    const std::size_t page = pageBytes();
    block.data()[0] = 'a';
    block.data()[5 * page + 7] = 'b';
    PagesMappedAhead ahead({{block.data(), block.bytes()}});
    if (!ahead.running()) {
        GTEST_SKIP() << "no second core, or a kernel without MADV_POPULATE_WRITE";
    }
    ahead.finish();
    EXPECT_EQ(block.residentPages(), block.bytes() / page);
    EXPECT_EQ(block.data()[0], 'a');
    EXPECT_EQ(block.data()[5 * page + 7], 'b');
    for (std::size_t i = 1; i < block.bytes(); i += page / 2) {
        if (i != 5 * page + 7) {
            ASSERT_EQ(block.data()[i], 0) << i;
        }
    }
}

// What the calling thread writes while the pages are being mapped stays written.
TEST(PagesMappedAhead, WritesOfTheCallingThreadMeanwhileAreKept) {
    FreshMapping block(32u << 20);
    ASSERT_NE(block.data(), nullptr);
    PagesMappedAhead ahead({{block.data(), block.bytes()}});
    if (!ahead.running()) {
        GTEST_SKIP() << "no second core, or a kernel without MADV_POPULATE_WRITE";
    }
    for (std::size_t i = 0; i < block.bytes(); i += 64) {
        block.data()[i] = static_cast<char>(1 + i % 127);
    }
    ahead.finish();
    for (std::size_t i = 0; i < block.bytes(); i += 64) {
        ASSERT_EQ(block.data()[i], static_cast<char>(1 + i % 127)) << i;
    }
}

// Destroyed at once, it stops at its next step: a gigabyte is not mapped.
TEST(PagesMappedAhead, StopsWhenDestroyedBeforeItEnds) {
    FreshMapping block(std::size_t{1} << 30);
    ASSERT_NE(block.data(), nullptr);
    { const PagesMappedAhead ahead({{block.data(), block.bytes()}}); }
    EXPECT_LT(block.residentPages(), block.bytes() / pageBytes());
}

// A range unmapped before its pages are mapped is refused by the kernel and left alone.
TEST(PagesMappedAhead, ARangeNoLongerMappedIsLeftAlone) {
    auto block = std::make_unique<FreshMapping>(16u << 20);
    ASSERT_NE(block->data(), nullptr);
    const MemoryRange range{block->data(), block->bytes()};
    block.reset();
    PagesMappedAhead ahead({range});
    ahead.finish();
    std::vector<unsigned char> flags(range.bytes / pageBytes());
    EXPECT_NE(::mincore(range.begin, range.bytes, flags.data()), 0) << "still unmapped";
}

TEST(PagesMappedAhead, SmallRangesAreNotWorthAThread) {
    FreshMapping block(1u << 20);
    ASSERT_NE(block.data(), nullptr);
    const PagesMappedAhead ahead({{block.data(), block.bytes()}});
    EXPECT_FALSE(ahead.running());
}

} // namespace
} // namespace bladeaxis

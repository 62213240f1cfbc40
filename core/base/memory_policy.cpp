#include "core/base/memory_policy.h"

#include "core/base/whole_pages.h"

#include <cstdint>
#include <cstdlib> // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bladeaxis {

void returnFreedHeapToTheSystem() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

std::size_t returnWholePagesToTheSystem(void* begin, std::size_t bytes) {
#if defined(__linux__)
    const PageRange pages = wholePagesIn(begin, bytes);
    if (pages.end <= pages.first) {
        return 0;
    }
    // Advice on memory this process owns cannot fail but for a kernel without it; the pages
    // then stay resident until the block is freed, as without the call.
    ::madvise(reinterpret_cast<void*>(pages.first), pages.end - pages.first, MADV_DONTNEED);
    return pages.end - reinterpret_cast<std::uintptr_t>(begin);
#else
    (void)begin;
    (void)bytes;
    return 0;
#endif
}

} // namespace bladeaxis

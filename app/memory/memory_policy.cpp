#include "app/memory/memory_policy.h"

#include <cstdlib> // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace bladeaxis::app {

void returnLargeBlocksToTheSystem() {
#if defined(__GLIBC__)
    constexpr int kMapBlocksFromBytes = 1 << 20;
    mallopt(M_MMAP_THRESHOLD, kMapBlocksFromBytes);
#endif
}

} // namespace bladeaxis::app

// A library that replaces the global operator new and delete, as core/base did until the
// executable's memory policy moved to app/memory: the allocator check must reject it
// (architecture.allocator_check_rejects_a_replaced_new).

#include <cstdlib>
#include <new>

void* operator new(std::size_t bytes) {
    if (void* block = std::malloc(bytes == 0 ? 1 : bytes)) {
        return block;
    }
    throw std::bad_alloc();
}

void operator delete(void* block) noexcept {
    std::free(block);
}

void operator delete(void* block, std::size_t) noexcept {
    std::free(block);
}

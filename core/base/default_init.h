#pragma once
// Vectors whose new elements are default-initialised: resize(n) or a size constructor leaves
// doubles and integers uninitialised instead of zero-filling them. Large per-point arrays are
// then first touched by the loops that fill them (on their own threads, see parallel.h), not by
// a serial zero fill on the calling thread that the loop overwrites anyway. Every other
// operation (push_back, assign, resize(n, value), copies) behaves as for std::vector.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace bladeaxis {

template <class T>
class DefaultInitAllocator : public std::allocator<T> {
  public:
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };

    DefaultInitAllocator() noexcept = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>& /*other*/) noexcept {}

    // Value-initialisation (what std::vector asks for) becomes default-initialisation.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }

    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <class T, class U>
bool operator==(const DefaultInitAllocator<T>& /*a*/, const DefaultInitAllocator<U>& /*b*/) {
    return true;
}

template <class T>
using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace bladeaxis

#pragma once
// Freeing what a container or a struct of containers holds while the object stays alive.

#include <utility>

namespace bladeaxis {

// Leaves `value` empty with its storage returned, where a vector's clear() would keep its
// capacity. The storage is swapped into an empty value that frees it: assigning an empty value
// would keep a string's buffer (libstdc++ copies a short string's characters into it).
template <class T>
void freeStorage(T& value) {
    T empty{};
    using std::swap;
    swap(value, empty);
}

} // namespace bladeaxis

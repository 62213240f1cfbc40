#pragma once
// Freeing what a container or a struct of containers holds while the object stays alive.

namespace bladeaxis {

// Leaves `value` empty with its storage returned: a moved-in empty value releases it, where a
// vector's clear() would keep its capacity.
template <class T>
void freeStorage(T& value) {
    value = T{};
}

} // namespace bladeaxis

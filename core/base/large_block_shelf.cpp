#include "core/base/large_block_shelf.h"

#include <cstdlib>

namespace bladeaxis {

namespace {

std::ptrdiff_t signedBytes(std::size_t bytes) {
    return static_cast<std::ptrdiff_t>(bytes);
}

} // namespace

void* LargeBlockShelf::take(std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    Place* best = nullptr;
    for (Place& place : places_) {
        const bool fits =
            place.block != nullptr && place.bytes >= bytes && place.bytes - bytes <= bytes / 32;
        if (fits && (best == nullptr || place.bytes < best->bytes)) {
            best = &place;
        }
    }
    if (best == nullptr) {
        return nullptr;
    }
    void* block = best->block;
    kept_ -= best->bytes;
    inUse_ += signedBytes(best->bytes);
    *best = Place{};
    return block;
}

void LargeBlockShelf::noteInUse(std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    inUse_ += signedBytes(bytes);
    if (inUse_ > mostInUse_) {
        mostInUse_ = inUse_;
    }
    freeLargestUntilWithinBound();
}

void LargeBlockShelf::noteGone(std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    inUse_ -= signedBytes(bytes);
}

bool LargeBlockShelf::keep(void* block, std::size_t usableBytes) {
    const std::lock_guard lock(mutex_);
    // In use to kept: the sum, and so the bound, is unchanged.
    inUse_ -= signedBytes(usableBytes);
    for (Place& place : places_) {
        if (place.block == nullptr) {
            place = Place{block, usableBytes};
            kept_ += usableBytes;
            return true;
        }
    }
    return false;
}

void LargeBlockShelf::freeAll() {
    const std::lock_guard lock(mutex_);
    for (Place& place : places_) {
        if (place.block != nullptr) {
            std::free(place.block);
            place = Place{};
        }
    }
    kept_ = 0;
}

std::size_t LargeBlockShelf::keptBytes() const {
    const std::lock_guard lock(mutex_);
    return kept_;
}

std::ptrdiff_t LargeBlockShelf::bytesInUse() const {
    const std::lock_guard lock(mutex_);
    return inUse_;
}

std::ptrdiff_t LargeBlockShelf::mostBytesInUse() const {
    const std::lock_guard lock(mutex_);
    return mostInUse_;
}

void LargeBlockShelf::freeLargestUntilWithinBound() {
    while (inUse_ + signedBytes(kept_) > mostInUse_) {
        Place* largest = nullptr;
        for (Place& place : places_) {
            if (place.block != nullptr && (largest == nullptr || place.bytes > largest->bytes)) {
                largest = &place;
            }
        }
        if (largest == nullptr) {
            return;
        }
        std::free(largest->block);
        kept_ -= largest->bytes;
        *largest = Place{};
    }
}

} // namespace bladeaxis

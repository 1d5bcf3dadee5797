// A bump allocator for per-sample scratch objects (a hit's BSDF), reset after each path sample, so the
// render loop does no heap allocation per ray (DESIGN.md §3). One arena per thread.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace illum {

class ScratchArena {
public:
    explicit ScratchArena(std::size_t bytes = 64 * 1024) : storage_(new std::byte[bytes]), capacity_(bytes) {}

    // Objects placed in the arena must be trivially destructible or have their destructor run by
    // the caller: reset() does not call destructors.
    template <class T, class... Args>
    T* make(Args&&... args) {
        void* p = allocate(sizeof(T), alignof(T));
        return new (p) T(std::forward<Args>(args)...);
    }

    void* allocate(std::size_t size, std::size_t align) {
        std::size_t offset = (used_ + align - 1) & ~(align - 1);
        if (offset + size > capacity_) throw std::bad_alloc();
        used_ = offset + size;
        return storage_.get() + offset;
    }

    void reset() { used_ = 0; }
    std::size_t used() const { return used_; }

private:
    std::unique_ptr<std::byte[]> storage_;
    std::size_t capacity_;
    std::size_t used_ = 0;
};

} // namespace illum

// A bump allocator for per-sample scratch objects (a hit's BSDF), reset after each path sample, so the
// render loop does no heap allocation per ray (DESIGN.md §3). One arena per thread; its storage owns its
// cache lines (line_aligned.h), as every path sample writes its first bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "illum/util/line_aligned.h"

namespace illum {

class ScratchArena {
public:
    explicit ScratchArena(std::size_t bytes = 64 * 1024)
        : storage_(static_cast<std::byte*>(allocate_lines(bytes))), capacity_(bytes) {}

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
    struct FreeLines {
        void operator()(std::byte* p) const { free_lines(p); }
    };
    std::unique_ptr<std::byte, FreeLines> storage_;
    std::size_t capacity_;
    std::size_t used_ = 0;
};

} // namespace illum

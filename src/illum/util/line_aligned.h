// Memory that one thread writes while others read their own data nearby: a thread's scratch arena, its
// subpath vertices, a chunk's splats. The heap packs allocations 16 bytes apart, so such a buffer can share
// a cache line with data every thread reads on every sample, and each write then takes the line from the
// other cores' caches: false sharing. Measured on the measured Cornell box with two threads, a thread's
// arena began 32 bytes after the light sampler's table of lights, and that table's load took 9% of the
// render (docs/performance.md). These buffers start on a boundary of kFalseSharingRange bytes and fill
// their last such block, so no other object lies in their lines. 128 rather than 64: Intel's L2 fetches
// lines in aligned pairs (the spatial prefetcher), so a neighbour in the pair's other line contends too
// (oneTBB's cache_aligned_allocator pads to 128 for the same reason).
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace illum {

inline constexpr std::size_t kFalseSharingRange = 128;

// `bytes` rounded up to whole blocks of kFalseSharingRange.
constexpr std::size_t whole_lines(std::size_t bytes) {
    return (bytes + kFalseSharingRange - 1) / kFalseSharingRange * kFalseSharingRange;
}

inline void* allocate_lines(std::size_t bytes) {
    return ::operator new(whole_lines(bytes), std::align_val_t(kFalseSharingRange));
}
inline void free_lines(void* p) { ::operator delete(p, std::align_val_t(kFalseSharingRange)); }

// A standard allocator whose blocks own their cache lines (above).
template <class T>
struct LineAlignedAllocator {
    using value_type = T;
    LineAlignedAllocator() = default;
    template <class U>
    LineAlignedAllocator(const LineAlignedAllocator<U>&) {}
    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / 2 / sizeof(T)) throw std::bad_array_new_length();
        return static_cast<T*>(allocate_lines(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t) { free_lines(p); }
    template <class U>
    bool operator==(const LineAlignedAllocator<U>&) const {
        return true;
    }
};

template <class T>
using LineAlignedVector = std::vector<T, LineAlignedAllocator<T>>;

} // namespace illum

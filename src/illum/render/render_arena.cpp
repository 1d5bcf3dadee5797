#include "illum/render/render_arena.h"

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define ILLUM_HAS_MXCSR 1
#endif

namespace illum {

namespace {
#ifdef ILLUM_HAS_MXCSR
constexpr unsigned kFtz = 0x8000; // MXCSR bit 15: results below the normal range become zero
constexpr unsigned kDaz = 0x0040; // MXCSR bit 6: denormal inputs are read as zero
#endif
} // namespace

RenderArena::RenderArena(int threads) : tbb::task_arena(threads) {
#ifdef ILLUM_HAS_MXCSR
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(saved | kFtz | kDaz);
    initialize(); // captures this thread's floating-point settings for the arena's work
    _mm_setcsr(saved);
#else
    initialize();
#endif
}

bool flushes_denormals() {
#ifdef ILLUM_HAS_MXCSR
    return (_mm_getcsr() & (kFtz | kDaz)) == (kFtz | kDaz);
#else
    return false;
#endif
}

} // namespace illum

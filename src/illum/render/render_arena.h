// The task arena a render runs its threads in, with denormal floats flushed to zero in every thread while
// it works there.
//
// Embree asks for the FTZ (flush-to-zero) and DAZ (denormals-are-zero) bits of MXCSR in every thread that
// calls it (Embree 3 manual, "Performance Recommendations"): denormal arithmetic takes a microcode assist
// per operation. On the measured Cornell box (walls exactly on x = 0 and y = 0, the suspects) Embree's time
// per ray was 3× that on the Bitterli box without them, and the same with them (docs/performance.md).
// oneTBB gives an arena the floating-point settings of the thread that initialises it and applies them to
// every task it runs and to execute()'s body, on any thread, restoring the thread's own afterwards; so the
// arena is initialised with both bits set, and code outside a render (the Python host, scene loading) keeps
// IEEE denormals. Every thread of a render flushes, so images stay the same at any thread count.
#pragma once

#include <oneapi/tbb/task_arena.h>

namespace illum {

class RenderArena final : public tbb::task_arena {
public:
    explicit RenderArena(int threads);
};

// Whether this thread flushes denormals now (FTZ and DAZ both set; false where the bits do not exist).
bool flushes_denormals();

} // namespace illum

// RenderArena: every task of a render's arena flushes denormals (FTZ and DAZ, which Embree asks for), on the
// workers and on the thread that calls execute(), which gets its own state back when execute() returns.
#include <gtest/gtest.h>

#include <atomic>
#include <oneapi/tbb/parallel_for.h>

#include "illum/render/render_arena.h"

namespace illum {
namespace {

// A product whose exact value (1e-39) is denormal: zero when results are flushed.
float denormal_product() {
    volatile float a = 1e-20f, b = 1e-19f;
    return a * b;
}

TEST(RenderArena, EveryThreadFlushesDenormalsInsideAndNotAfter) {
#if defined(__SSE__) || defined(__x86_64__)
    ASSERT_FALSE(flushes_denormals());
    ASSERT_GT(denormal_product(), 0.0f);
    std::atomic<int> tasks{0}, flushed{0}, zero{0};
    {
        RenderArena arena(2);
        arena.execute([&] {
            EXPECT_TRUE(flushes_denormals()); // the calling thread
            tbb::parallel_for(0, 2000, [&](int) {
                ++tasks;
                if (flushes_denormals()) ++flushed;
                if (denormal_product() == 0.0f) ++zero;
            });
            // A render's arena made inside another's: flushing there too, and the outer state holds after.
            RenderArena inner(1);
            inner.execute([&] { EXPECT_TRUE(flushes_denormals()); });
            EXPECT_TRUE(flushes_denormals());
        });
        EXPECT_FALSE(flushes_denormals()); // restored on leaving
    }
    EXPECT_EQ(tasks.load(), 2000);
    EXPECT_EQ(flushed.load(), 2000);
    EXPECT_EQ(zero.load(), 2000);
    EXPECT_FALSE(flushes_denormals());
    EXPECT_GT(denormal_product(), 0.0f);
#else
    GTEST_SKIP() << "no MXCSR on this architecture";
#endif
}

} // namespace
} // namespace illum

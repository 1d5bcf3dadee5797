// util/line_aligned.h: buffers that one thread writes own their cache lines, so no other object shares a
// line (or the prefetcher's pair of lines) with them.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "illum/camera/film.h"
#include "illum/util/arena.h"
#include "illum/util/line_aligned.h"

namespace illum {
namespace {

bool on_boundary(const void* p) { return std::uintptr_t(p) % kFalseSharingRange == 0; }

TEST(LineAligned, RoundsToWholeBlocks) {
    EXPECT_EQ(whole_lines(0), 0u);
    EXPECT_EQ(whole_lines(1), kFalseSharingRange);
    EXPECT_EQ(whole_lines(kFalseSharingRange), kFalseSharingRange);
    EXPECT_EQ(whole_lines(kFalseSharingRange + 1), 2 * kFalseSharingRange);
}

// Small blocks allocated one after the other: the heap would pack them 16 or 32 bytes apart. Each starts on
// a boundary, so none lies in another's lines.
TEST(LineAligned, SmallBlocksStartOnBoundariesAndDoNotShareLines) {
    std::vector<void*> blocks;
    for (int i = 0; i < 16; ++i) blocks.push_back(allocate_lines(8));
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        EXPECT_TRUE(on_boundary(blocks[i])) << blocks[i];
        for (std::size_t j = 0; j < i; ++j) {
            std::uintptr_t a = std::uintptr_t(blocks[i]), b = std::uintptr_t(blocks[j]);
            EXPECT_GE(a > b ? a - b : b - a, kFalseSharingRange);
        }
    }
    for (void* p : blocks) free_lines(p);
}

TEST(LineAligned, VectorStorageStartsOnABoundary) {
    for (std::size_t n : {1u, 3u, 17u, 1000u}) {
        LineAlignedVector<float> v(n, 1.0f);
        EXPECT_TRUE(on_boundary(v.data())) << n;
        v.resize(3 * n + 5); // a reallocation keeps the alignment
        EXPECT_TRUE(on_boundary(v.data())) << n;
        EXPECT_EQ(v[0], 1.0f);
    }
}

// Every path sample writes the start of its thread's scratch arena (the hit's BSDF). Eight arenas: with the
// heap's own 16-byte alignment all eight would be on boundaries by chance once in 8^8 runs.
TEST(LineAligned, ScratchArenasOwnTheirLines) {
    std::vector<std::unique_ptr<ScratchArena>> arenas;
    for (int i = 0; i < 8; ++i) {
        arenas.push_back(std::make_unique<ScratchArena>(1000));
        EXPECT_TRUE(on_boundary(arenas.back()->allocate(1, 1)));
    }
}

// Threads write neighbouring tiles of one film: its sums start on a boundary, so 16-pixel tile rows (512
// bytes) fall on whole blocks.
TEST(LineAligned, FilmSumsStartOnABoundary) {
    for (int w : {4, 17, 64, 320}) {
        Film film(w, 3);
        EXPECT_TRUE(on_boundary(film.accumulators().data())) << w;
    }
}

} // namespace
} // namespace illum

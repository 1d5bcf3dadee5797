// util/in_place.h: assign_in_place builds a function's result in the object's own storage.
#include <gtest/gtest.h>

#include "illum/util/in_place.h"

namespace illum {
namespace {

// Neither copyable nor movable: assign_in_place compiles for it only because the result is built where
// it is kept (C++17's guaranteed copy elision), which is the whole point of the helper.
struct Pinned {
    float value[9];
    explicit Pinned(float v) {
        for (float& x : value) x = v;
    }
    Pinned(const Pinned&) = delete;
    Pinned(Pinned&&) = delete;
    Pinned& operator=(const Pinned&) = delete;
    Pinned& operator=(Pinned&&) = delete;
};

Pinned make_pinned(float v) { return Pinned(v); }

TEST(AssignInPlace, BuildsTheResultInTheObjectWithoutACopy) {
    Pinned p(1.0f);
    const Pinned* address = &p;
    assign_in_place(p, [] { return make_pinned(7.0f); });
    EXPECT_EQ(&p, address);
    for (float x : p.value) EXPECT_EQ(x, 7.0f);
}

struct Pair {
    float a, b;
};
Pair swapped(float a, float b) { return Pair{b, a}; }

TEST(AssignInPlace, ArgumentsAreReadBeforeTheResultIsBuilt) {
    // The maker's call may take the old object's fields as arguments (walk's `ray = hit.spawn_ray(ray.d)`
    // does): they are copied into the parameters before the result is built over them.
    Pair p{1.0f, 2.0f};
    assign_in_place(p, [&] { return swapped(p.a, p.b); });
    EXPECT_EQ(p.a, 2.0f);
    EXPECT_EQ(p.b, 1.0f);
}

} // namespace
} // namespace illum

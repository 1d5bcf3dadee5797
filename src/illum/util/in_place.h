// Assigning a function's result without a temporary.
//
// `x = f()` with a result returned in memory (any struct larger than two registers) has f() write a
// temporary, field by field, and then copies it into x with a few wide loads and stores. Each wide load
// overlaps several of f()'s narrower stores that are still in the store buffer, which the processor
// cannot forward to it: the load waits until those stores reach the cache (a store-forwarding stall,
// about a dozen cycles; Intel 64 and IA-32 Architectures Optimization Reference Manual, "Store
// Forwarding"; AMD's Software Optimization Guide likewise). Measured by perf on BDPT's hot loop: a
// returned ray, BSDF or connection end copied right after its call took up to a tenth of the function's
// time (docs/performance.md, "Results built where they are kept").
//
// assign_in_place(x, [&] { return f(args); }) ends x's lifetime and builds the result in its storage: with
// C++17's guaranteed copy elision x's address is f()'s return slot, so nothing is copied. Hence f may take
// x's fields as arguments (copied before it runs) but must not read x through a reference while it builds
// its result, and T must have no const or reference members (so that the name x denotes the new object,
// C++20 [basic.life]/8).
#pragma once

#include <memory>
#include <new>
#include <type_traits>

namespace illum {

template <class T, class Make>
requires std::is_trivially_destructible_v<T> && std::is_same_v<std::invoke_result_t<Make>, T>
inline void assign_in_place(T& object, Make&& make) {
    ::new (static_cast<void*>(std::addressof(object))) T(make());
}

} // namespace illum

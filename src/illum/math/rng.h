// Pseudo-random numbers and integer hashing.
//
// PCG32 after M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good Algorithms
// for Random Number Generation" (2014): a 64-bit linear congruential generator whose output is permuted
// by XSH-RR (xorshift high bits, then a random rotation chosen by the top bits), giving 32 bits per step.
// The increment selects one of 2^63 independent streams.
#pragma once

#include <cstdint>
#include <type_traits>

namespace illum {

// 64-bit finaliser of splitmix64 (G. Steele, D. Lea, C. Flood, "Fast Splittable Pseudorandom Number
// Generators", OOPSLA 2014; the constants are D. Stafford's "Mix13" variant): a bijection on 64-bit
// integers with full avalanche.
constexpr uint64_t mix_bits(uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ULL;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebULL;
    v ^= v >> 31;
    return v;
}

// Hash of a list of integral (or enum) values, e.g. hash(seed, pixel.x, pixel.y, sample_index). Order
// matters: hash(a, b) != hash(b, a) in general. Each value is folded into the state and re-mixed, so every
// input bit influences every output bit.
template <typename... Args>
constexpr uint64_t hash(Args... args) {
    static_assert(((std::is_integral_v<Args> || std::is_enum_v<Args>)&&...),
                  "hash() takes integral or enum values");
    uint64_t h = 0x243f6a8885a308d3ULL; // digits of π: an arbitrary non-zero start
    (
        [&](auto v) {
            uint64_t x;
            if constexpr (std::is_enum_v<decltype(v)>)
                x = static_cast<uint64_t>(static_cast<std::underlying_type_t<decltype(v)>>(v));
            else
                x = static_cast<uint64_t>(v);
            // Golden-ratio increment keeps a zero input from being a no-op on the state.
            h = mix_bits(h ^ (x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
        }(args),
        ...);
    return h;
}

class PCG32 {
public:
    static constexpr uint64_t kDefaultState = 0x853c49e6748fea9bULL;
    static constexpr uint64_t kDefaultStream = 0xda3e39cb94b95bdbULL;
    static constexpr uint64_t kMultiplier = 0x5851f42d4c957f2dULL; // 6364136223846793005

    constexpr PCG32() : state_(kDefaultState), inc_(kDefaultStream) {}
    constexpr PCG32(uint64_t seed, uint64_t stream = 1) { set_sequence(seed, stream); }

    // Seeds as in the paper's reference initialisation: choose the stream, step once, add the seed, step
    // again, so that nearby seeds do not give nearby first outputs.
    constexpr void set_sequence(uint64_t seed, uint64_t stream = 1) {
        state_ = 0;
        inc_ = (stream << 1) | 1;
        uniform_uint32();
        state_ += seed;
        uniform_uint32();
    }

    constexpr uint32_t uniform_uint32() {
        uint64_t old = state_;
        state_ = old * kMultiplier + inc_;
        auto xorshifted = static_cast<uint32_t>(((old >> 18) ^ old) >> 27);
        auto rot = static_cast<uint32_t>(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }

    // Uniform in [0, 1): the top 24 bits scaled by 2^-24, so 1 is never returned and every value is exact.
    constexpr float uniform_float() { return float(uniform_uint32() >> 8) * 0x1p-24f; }
    // Uniform in [0, 1) with 53 bits.
    constexpr double uniform_double() {
        uint64_t hi = uniform_uint32(), lo = uniform_uint32();
        return double(((hi << 32) | lo) >> 11) * 0x1p-53;
    }

    // Moves the generator delta steps forward (or backward, delta taken mod 2^64) in O(log delta) time:
    // the composition of LCG steps is itself an LCG, squared up by repeated doubling (F. Brown, "Random
    // Number Generation with Arbitrary Strides", Trans. Am. Nucl. Soc. 1994).
    constexpr void advance(int64_t delta) {
        uint64_t cur_mult = kMultiplier, cur_plus = inc_, acc_mult = 1, acc_plus = 0;
        for (auto d = static_cast<uint64_t>(delta); d > 0; d >>= 1) {
            if (d & 1) {
                acc_mult *= cur_mult;
                acc_plus = acc_plus * cur_mult + cur_plus;
            }
            cur_plus = (cur_mult + 1) * cur_plus;
            cur_mult *= cur_mult;
        }
        state_ = acc_mult * state_ + acc_plus;
    }

    constexpr bool operator==(const PCG32&) const = default;

private:
    uint64_t state_ = kDefaultState, inc_ = kDefaultStream;
};

} // namespace illum

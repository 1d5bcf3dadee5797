// Building blocks of the low-discrepancy samplers (sampler.h): radical inverses in prime bases with their
// digit permutations and nested scrambles, the inverse radical inverse and modular inverses the Halton
// sampler's pixel mapping needs, hashed permutations of [0, n), scramblers of base-2 (Sobol) fractions and
// Morton codes.
//
// References: H. Niederreiter, "Random Number Generation and Quasi-Monte Carlo Methods" (SIAM 1992) for
// radical inverses and (t, m, s)-nets; A. Owen, "Randomly Permuted (t,m,s)-Nets and (t,s)-Sequences"
// (1995) for nested scrambling; A. Kensler, "Correlated Multi-Jittered Sampling" (Pixar TM 13-01, 2013)
// for permutations of [0, n) by cycle-walking a bijective hash; B. Burley, "Practical Hash-based Owen
// Scrambling" (JCGT 9(4), 2020) for the fast base-2 Owen scramble; M. Pharr, W. Jakob, G. Humphreys,
// "Physically Based Rendering", 4th ed., chapter 8 for the samplers built from them.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "illum/math/rng.h"
#include "illum/render/sampler.h"

namespace illum::low_discrepancy {

// The first kPrimeCount primes (2, 3, 5, ..., 7919), found by trial division when compiled.
inline constexpr int kPrimeCount = 1000;
const std::array<uint32_t, kPrimeCount>& primes();

// Radical inverse Φ_b(a) = Σ d_i b^-(i+1) of a = Σ d_i b^i, b = primes()[base_index], in [0, 1).
float radical_inverse(int base_index, uint64_t a);

// The integer whose first n_digits base-b digits are those of `inverse` in reverse order: for
// inverse = b^n Φ_b(a) with a < b^n, returns a.
uint64_t inverse_radical_inverse(uint64_t inverse, int base, int n_digits);

// x with x a ≡ 1 (mod n) for coprime a, n > 0 (extended Euclid).
int64_t multiplicative_inverse(int64_t a, int64_t n);

// Element i of a pseudo-random permutation of [0, n) chosen by seed (Kensler 2013: a bijective hash on
// the smallest power-of-two range holding n, iterated until the value falls below n). i < n.
uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t seed);

// Random digit permutations of one prime base: digit i of the fraction (the i-th digit of the index) is
// replaced by perm[i][digit], each perm[i] an independent permutation of [0, b); enough digits for float
// precision (b^-n_digits < 2^-24). Then Φ applied to the permuted digits, including the leading zeros of a,
// is a scrambled radical inverse (pbrt-v4's "permutedigits").
struct DigitPermutations {
    int base = 2, n_digits = 0;
    std::vector<uint16_t> perm; // n_digits x base
};
// One table per prime of primes(), for a seed.
std::vector<DigitPermutations> make_digit_permutations(uint64_t seed);

float scrambled_radical_inverse(const DigitPermutations& p, uint64_t a);

// Nested (Owen) scramble of Φ_b(a): the digit at position i is shifted by a random amount mod b chosen by
// a hash of (seed, the digits above it), so every subtree of the b-ary digit tree is permuted on its own.
float owen_scrambled_radical_inverse(int base_index, uint64_t a, uint64_t seed);

// Scramblers of a 32-bit base-2 fraction (the bits, most significant first).
// Random digital shift: x XOR seed.
inline uint32_t permute_digits_base2(uint32_t x, uint32_t seed) { return x ^ seed; }
// Burley's hash approximation of a nested uniform scramble.
inline uint32_t fast_owen_base2(uint32_t x, uint32_t seed) {
    return sampling_detail::nested_uniform_scramble(x, seed);
}
// Exact nested uniform scramble: bit b flipped by a hashed bit of (seed, the bits above b).
uint32_t owen_base2(uint32_t x, uint32_t seed);

inline uint32_t scramble_base2(uint32_t x, uint32_t seed, Randomization r) {
    switch (r) {
    case Randomization::none:
        return x;
    case Randomization::permute_digits:
        return permute_digits_base2(x, seed);
    case Randomization::fast_owen:
        return fast_owen_base2(x, seed);
    case Randomization::owen:
        return owen_base2(x, seed);
    }
    return x;
}

// Interleaves the bits of x (even positions) and y (odd positions): the Morton (Z-order) code.
inline uint64_t spread_bits(uint32_t v) {
    uint64_t x = v;
    x = (x | (x << 16)) & 0x0000ffff0000ffffULL;
    x = (x | (x << 8)) & 0x00ff00ff00ff00ffULL;
    x = (x | (x << 4)) & 0x0f0f0f0f0f0f0f0fULL;
    x = (x | (x << 2)) & 0x3333333333333333ULL;
    x = (x | (x << 1)) & 0x5555555555555555ULL;
    return x;
}
inline uint64_t morton_2d(uint32_t x, uint32_t y) { return spread_bits(x) | (spread_bits(y) << 1); }

} // namespace illum::low_discrepancy

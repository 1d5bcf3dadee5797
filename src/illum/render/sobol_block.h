// The Owen-scrambled Sobol' sampler's draws, eight dimensions at a time (sampler.h, kind "sobol").
//
// A draw of dimension d of a pixel sample is two chains of integer hashing (Burley 2020, sampler.h): the
// per-dimension seeds from the pixel's hash, the index shuffle, the Sobol' point and the scramble of each
// coordinate. One draw is about 110 instructions whose latency lies between a path's hit and its next
// direction. The eight dimensions 1 + 8b .. 8 + 8b are independent of each other, so on a processor with
// AVX2 they are computed together, one dimension per 32-bit lane, in about a fifth of the instructions, and
// the path reads them from the sampler as it goes. The lanes compute exactly the scalar draws (integer
// arithmetic throughout; the final float is exact), so images do not depend on which way they were made.
#pragma once

#include <cstdint>

#include "illum/math/rng.h"
#include "illum/math/vector.h"

namespace illum::sampling_detail {

inline uint32_t reverse_bits(uint32_t v) {
    // Bits within each byte, then the bytes by one byte swap.
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    return __builtin_bswap32(v);
}

// Sobol dimension 0: the van der Corput radical inverse in base 2, as a 32-bit fraction.
inline uint32_t sobol_dim0(uint32_t index) { return reverse_bits(index); }
// Sobol dimension 1: XOR of the direction numbers v_i for the set bits i of index, with v_0 = 2^31 and
// v_i = v_{i-1} ^ (v_{i-1} >> 1). Defined out of line with byte-wise tables.
uint32_t sobol_dim1(uint32_t index);
// The same, bit-reversed, of the bit-reversed index: reverse_bits(sobol_dim1(i)) from reverse_bits(i). The
// map is linear over GF(2) either way, so it is tabulated alike; the Owen-scrambled sampler works on
// reversed indices and values and saves two reversals.
uint32_t sobol_dim1_reversed(uint32_t reversed_index);

// reverse_bits(sobol_dim1(i)) from i itself, without tables. v_i = (1 + S)^i v_0 with S the shift by one
// place, so bit i of the index sets fraction digit j of the value when C(i, j) is odd, that is (Lucas'
// theorem) when the bits of j are a subset of those of i. Digit j of the value is thus the XOR of the index
// bits i ⊇ j: the superset transform over the five bits of a bit position, one shift-and-mask step per bit.
inline uint32_t sobol_dim1_reversed_from_index(uint32_t i) {
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    i ^= (i >> 16) & 0x0000ffffu;
    return i;
}

// The Laine-Karras hash (S. Laine, T. Karras, "Stratified Sampling for Stochastic Transparency", EGSR 2011)
// with the constants Burley 2020 found to give better-mixed permutations. Each output bit depends only on
// the same and lower input bits, so applied to a bit-reversed fraction it is a nested uniform scramble.
inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen scramble of a 32-bit fraction (or, for index shuffling, of a 32-bit index seen as a fraction).
inline uint32_t nested_uniform_scramble(uint32_t x, uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

// A 32-bit fraction to float in [0, 1): the top 24 bits times 2^-24 (rounding could otherwise give 1).
inline float bits_to_unit_float(uint32_t x) { return float(x >> 8) * 0x1p-24f; }

// Dimension dim's hash, the seed of the per-(pixel, dimension) randomisations of the sobol, paddedsobol,
// stratified and pmj02bn kinds: one finaliser round per dimension (a Weyl step keeps dimensions apart); the
// pixel hash already mixes (seed, pixel).
inline uint64_t dimension_hash(uint64_t pixel_hash, uint32_t dim) {
    return mix_bits(pixel_hash + (uint64_t(dim) + 1) * 0x9e3779b97f4a7c15ULL);
}

// Sample `index` (given as reverse_bits(index)) of Owen-scrambled Sobol' dimensions (0, 1) with one
// dimension's seeds: the index is itself Owen-scrambled (shuffled), i = nested_uniform_scramble(index), then
// each coordinate nested_uniform_scramble(sobol_dimk(i)). Kept in reversed bits where the Laine-Karras
// permutation wants them: LK(reverse(index)) is reverse(i); sobol_dim0(i) = reverse(i), so x =
// reverse(LK(i)); y comes from sobol_dim1_reversed(reverse(i)). A 1D draw is the x of the 2D one.
inline Point2f sobol_owen_2d_seeded(uint32_t reversed_index, uint32_t index_seed, uint32_t x_seed,
                                    uint32_t y_seed) {
    uint32_t i_reversed = laine_karras_permutation(reversed_index, index_seed);
    uint32_t x = reverse_bits(laine_karras_permutation(reverse_bits(i_reversed), x_seed));
    uint32_t y = reverse_bits(laine_karras_permutation(sobol_dim1_reversed(i_reversed), y_seed));
    return {bits_to_unit_float(x), bits_to_unit_float(y)};
}
// The seeds of dimension dim: uint32_t(h) shuffles the index, uint32_t(h >> 32) scrambles x and
// uint32_t(mix_bits(h)) y, with h = dimension_hash(pixel_hash, dim).
inline Point2f sobol_owen_2d(uint64_t pixel_hash, uint32_t reversed_index, uint32_t dim) {
    const uint64_t h = dimension_hash(pixel_hash, dim);
    return sobol_owen_2d_seeded(reversed_index, uint32_t(h), uint32_t(h >> 32), uint32_t(mix_bits(h)));
}
inline float sobol_owen_1d(uint64_t pixel_hash, uint32_t reversed_index, uint32_t dim) {
    uint64_t h = dimension_hash(pixel_hash, dim);
    uint32_t i = reverse_bits(laine_karras_permutation(reversed_index, uint32_t(h)));
    return bits_to_unit_float(reverse_bits(laine_karras_permutation(i, uint32_t(h >> 32))));
}

constexpr uint32_t kSobolBlock = 8; // dimensions per block

// The seeds of a block's dimensions: they depend on the pixel and the dimension, not on the sample index,
// so the samples of one pixel share them (half of a block's work is the two hashes).
struct SobolBlockSeeds {
    uint32_t index[kSobolBlock]; // as sobol_owen_2d's: the index shuffle's,
    uint32_t x[kSobolBlock];     // x's scramble's
    uint32_t y[kSobolBlock];     // and y's
};

// Whether the blocks run in vector lanes here (AVX2); otherwise the sampler draws dimension by dimension.
bool sobol_blocks_vectorised();
// The seeds of dimensions first_dim .. first_dim + kSobolBlock - 1.
void sobol_block_seeds(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds);
// x[k], y[k] = sobol_owen_2d(pixel_hash, reversed_index, first_dim + k) for k < kSobolBlock, from the
// block's seeds; in AVX2 lanes where the processor has them, else one after another.
void sobol_block(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y);
// The two ways, for the tests (the _avx2 ones only where sobol_blocks_vectorised()).
void sobol_block_seeds_scalar(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds);
void sobol_block_seeds_avx2(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds);
void sobol_block_scalar(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y);
void sobol_block_avx2(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y);

} // namespace illum::sampling_detail

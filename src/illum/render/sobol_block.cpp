#include "illum/render/sobol_block.h"

#if defined(__x86_64__)
#include <immintrin.h>
#define ILLUM_SOBOL_AVX2 1
#endif

namespace illum::sampling_detail {

void sobol_block_seeds_scalar(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds) {
    for (uint32_t k = 0; k < kSobolBlock; ++k) {
        const uint64_t h = dimension_hash(pixel_hash, first_dim + k);
        seeds->index[k] = uint32_t(h);
        seeds->x[k] = uint32_t(h >> 32);
        seeds->y[k] = uint32_t(mix_bits(h));
    }
}

void sobol_block_scalar(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y) {
    for (uint32_t k = 0; k < kSobolBlock; ++k) {
        const Point2f p = sobol_owen_2d_seeded(reversed_index, seeds.index[k], seeds.x[k], seeds.y[k]);
        x[k] = p.x;
        y[k] = p.y;
    }
}

#if ILLUM_SOBOL_AVX2

namespace {

#define ILLUM_AVX2 __attribute__((target("avx2")))

// a · c mod 2^64 in each 64-bit lane: AVX2 multiplies 32 × 32 → 64 bits, so
// a c = lo(a) lo(c) + 2^32 (hi(a) lo(c) + lo(a) hi(c)) mod 2^64.
ILLUM_AVX2 inline __m256i mul64(__m256i a, uint64_t c) {
    const __m256i c_lo = _mm256_set1_epi64x(int64_t(c & 0xffffffffu));
    const __m256i c_hi = _mm256_set1_epi64x(int64_t(c >> 32));
    __m256i low = _mm256_mul_epu32(a, c_lo);
    __m256i cross =
        _mm256_add_epi64(_mm256_mul_epu32(_mm256_srli_epi64(a, 32), c_lo), _mm256_mul_epu32(a, c_hi));
    return _mm256_add_epi64(low, _mm256_slli_epi64(cross, 32));
}

// rng.h's mix_bits in each 64-bit lane.
ILLUM_AVX2 inline __m256i mix_bits4(__m256i v) {
    v = _mm256_xor_si256(v, _mm256_srli_epi64(v, 30));
    v = mul64(v, 0xbf58476d1ce4e5b9ULL);
    v = _mm256_xor_si256(v, _mm256_srli_epi64(v, 27));
    v = mul64(v, 0x94d049bb133111ebULL);
    return _mm256_xor_si256(v, _mm256_srli_epi64(v, 31));
}

// The low (high) 32-bit halves of the 64-bit lanes of a (lanes 0-3) and b (4-7), as eight 32-bit lanes in
// that order. shuffle_ps interleaves per 128-bit half: a0 a1 b0 b1 | a2 a3 b2 b3; the permute puts the
// pairs in order.
ILLUM_AVX2 inline __m256i low_halves(__m256i a, __m256i b) {
    __m256 s = _mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), _MM_SHUFFLE(2, 0, 2, 0));
    return _mm256_permute4x64_epi64(_mm256_castps_si256(s), _MM_SHUFFLE(3, 1, 2, 0));
}
ILLUM_AVX2 inline __m256i high_halves(__m256i a, __m256i b) {
    __m256 s = _mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), _MM_SHUFFLE(3, 1, 3, 1));
    return _mm256_permute4x64_epi64(_mm256_castps_si256(s), _MM_SHUFFLE(3, 1, 2, 0));
}

ILLUM_AVX2 inline __m256i laine_karras8(__m256i x, __m256i seed) {
    x = _mm256_add_epi32(x, seed);
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(int32_t(0x6c50b47cu))));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(int32_t(0xb82f1e52u))));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(int32_t(0xc7afe638u))));
    return _mm256_xor_si256(x, _mm256_mullo_epi32(x, _mm256_set1_epi32(int32_t(0x8d22f6e6u))));
}

// reverse_bits in each 32-bit lane: each byte's nibbles reversed through a 16-entry table (pshufb), then
// the bytes of each lane swapped.
ILLUM_AVX2 inline __m256i reverse_bits8(__m256i x) {
    // rev4(n) for the high nibble's place (from the low nibble) and for the low nibble's (from the high).
    const __m256i to_high = _mm256_setr_epi8(0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0, 0x60, 0xe0, 0x10, 0x90, 0x50,
                                             0xd0, 0x30, 0xb0, 0x70, 0xf0, 0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0,
                                             0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0, 0x30, 0xb0, 0x70, 0xf0);
    const __m256i to_low =
        _mm256_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0,
                         0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf);
    const __m256i byte_swap = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1,
                                               0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
    const __m256i nibble = _mm256_set1_epi8(0x0f);
    __m256i lo = _mm256_and_si256(x, nibble), hi = _mm256_and_si256(_mm256_srli_epi16(x, 4), nibble);
    __m256i r = _mm256_or_si256(_mm256_shuffle_epi8(to_high, lo), _mm256_shuffle_epi8(to_low, hi));
    return _mm256_shuffle_epi8(r, byte_swap);
}

ILLUM_AVX2 inline __m256i superset_transform8(__m256i i) {
    i = _mm256_xor_si256(i, _mm256_and_si256(_mm256_srli_epi32(i, 1), _mm256_set1_epi32(0x55555555)));
    i = _mm256_xor_si256(i, _mm256_and_si256(_mm256_srli_epi32(i, 2), _mm256_set1_epi32(0x33333333)));
    i = _mm256_xor_si256(i, _mm256_and_si256(_mm256_srli_epi32(i, 4), _mm256_set1_epi32(0x0f0f0f0f)));
    i = _mm256_xor_si256(i, _mm256_and_si256(_mm256_srli_epi32(i, 8), _mm256_set1_epi32(0x00ff00ff)));
    return _mm256_xor_si256(i, _mm256_srli_epi32(i, 16)); // the mask 0x0000ffff: the shift clears the rest
}

ILLUM_AVX2 inline __m256i load(const uint32_t* p) {
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

ILLUM_AVX2 inline __m256 unit_floats8(__m256i bits) {
    return _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(bits, 8)), _mm256_set1_ps(0x1p-24f));
}

} // namespace

ILLUM_AVX2 void sobol_block_seeds_avx2(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds) {
    constexpr uint64_t kWeyl = 0x9e3779b97f4a7c15ULL;
    // dimension_hash of dimensions first_dim + k: the Weyl steps k · kWeyl added to dimension
    // first_dim's.
    const __m256i base = _mm256_set1_epi64x(int64_t(pixel_hash + (uint64_t(first_dim) + 1) * kWeyl));
    const __m256i steps0 = _mm256_setr_epi64x(0, int64_t(kWeyl), int64_t(2 * kWeyl), int64_t(3 * kWeyl));
    const __m256i steps1 =
        _mm256_setr_epi64x(int64_t(4 * kWeyl), int64_t(5 * kWeyl), int64_t(6 * kWeyl), int64_t(7 * kWeyl));
    const __m256i h0 = mix_bits4(_mm256_add_epi64(base, steps0)),
                  h1 = mix_bits4(_mm256_add_epi64(base, steps1));
    const __m256i g0 = mix_bits4(h0), g1 = mix_bits4(h1);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds->index), low_halves(h0, h1));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds->x), high_halves(h0, h1));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(seeds->y), low_halves(g0, g1));
}

ILLUM_AVX2 void sobol_block_avx2(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y) {
    const __m256i i_reversed = laine_karras8(_mm256_set1_epi32(int32_t(reversed_index)), load(seeds.index));
    const __m256i i = reverse_bits8(i_reversed);
    const __m256i xs = reverse_bits8(laine_karras8(i, load(seeds.x)));
    const __m256i ys = reverse_bits8(laine_karras8(superset_transform8(i), load(seeds.y)));
    _mm256_storeu_ps(x, unit_floats8(xs));
    _mm256_storeu_ps(y, unit_floats8(ys));
}

bool sobol_blocks_vectorised() {
#if defined(__AVX2__)
    return true;
#else
    static const bool avx2 = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return avx2;
#endif
}

void sobol_block_seeds(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds) {
    if (sobol_blocks_vectorised())
        sobol_block_seeds_avx2(pixel_hash, first_dim, seeds);
    else
        sobol_block_seeds_scalar(pixel_hash, first_dim, seeds);
}

void sobol_block(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y) {
    if (sobol_blocks_vectorised())
        sobol_block_avx2(seeds, reversed_index, x, y);
    else
        sobol_block_scalar(seeds, reversed_index, x, y);
}

#else

bool sobol_blocks_vectorised() { return false; }
void sobol_block_seeds_avx2(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds) {
    sobol_block_seeds_scalar(pixel_hash, first_dim, seeds);
}
void sobol_block_avx2(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y) {
    sobol_block_scalar(seeds, reversed_index, x, y);
}
void sobol_block_seeds(uint64_t pixel_hash, uint32_t first_dim, SobolBlockSeeds* seeds) {
    sobol_block_seeds_scalar(pixel_hash, first_dim, seeds);
}
void sobol_block(const SobolBlockSeeds& seeds, uint32_t reversed_index, float* x, float* y) {
    sobol_block_scalar(seeds, reversed_index, x, y);
}

#endif

} // namespace illum::sampling_detail

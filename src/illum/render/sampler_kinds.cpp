// The samplers after independent and sobol (sampler.h): zsobol, paddedsobol, halton, pmj02bn, stratified,
// as pbrt-v4 defines them (src/pbrt/samplers.h), from the building blocks of low_discrepancy.h and pmj02.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <oneapi/tbb/parallel_for.h>

#include "illum/render/low_discrepancy.h"
#include "illum/render/pmj02.h"
#include "illum/render/sampler.h"
#include "illum/util/error.h"

namespace illum {

namespace {

using namespace low_discrepancy;
using sampling_detail::bits_to_unit_float;
using sampling_detail::dimension_hash;
using sampling_detail::sobol_dim0;
using sampling_detail::sobol_dim1;

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
constexpr uint64_t kGolden = 0x9e3779b97f4a7c15ULL;

// pbrt-v4's table sizes: five pmj02bn sequences of 2^16 points; Halton pixels repeat every 128.
constexpr int kPmjSets = 5, kPmjPoints = 1 << 16, kMaxHaltonResolution = 128;

// The 24 permutations of {0, 1, 2, 3}, in lexicographic order.
constexpr std::array<std::array<uint8_t, 4>, 24> make_base4_permutations() {
    std::array<std::array<uint8_t, 4>, 24> p{};
    int n = 0;
    for (uint8_t a = 0; a < 4; ++a)
        for (uint8_t b = 0; b < 4; ++b)
            for (uint8_t c = 0; c < 4; ++c)
                for (uint8_t d = 0; d < 4; ++d)
                    if (a != b && a != c && a != d && b != c && b != d && c != d)
                        p[size_t(n++)] = {a, b, c, d};
    return p;
}
constexpr auto kBase4Permutations = make_base4_permutations();

int ceil_log2(int v) {
    int k = 0;
    while ((1 << k) < v) ++k;
    return k;
}

float fixed_to_float(uint32_t x) { return bits_to_unit_float(x); }

// pbrt-v4 has 48 blue-noise tiles of 128^2; these are 8 of 64^2 (pmj02.h), each dimension a tile and a
// toroidal and value offset of its own.
constexpr int kBlueNoiseTiles = 8;

// Fixed seeds, as pbrt-v4's tables are fixed.
uint64_t pmj_seed(int set) { return hash(0x706d6a3032ULL, set); }

// The pixel offsets' pmj02 sequence (2^16 points) and the blue-noise tiles, generated once per process on
// first use (docs/performance.md has the time this takes).
struct Pmj02Data {
    std::vector<pmj02::FixedPoint2> pixel_sequence;
    std::array<std::vector<float>, kBlueNoiseTiles> blue_noise;
};

const Pmj02Data& pmj02_data() {
    static const Pmj02Data data = [] {
        Pmj02Data d;
        tbb::parallel_for(0, 1 + kBlueNoiseTiles, [&](int k) {
            if (k == 0)
                d.pixel_sequence = pmj02::generate(kPmjPoints, pmj_seed(0));
            else
                d.blue_noise[size_t(k - 1)] = pmj02::blue_noise_tile(hash(0xb1e5eedULL, k));
        });
        return d;
    }();
    return data;
}

} // namespace

struct SamplerTables {
    std::vector<DigitPermutations> digit_permutations; // halton with permutedigits
    const Pmj02Data* pmj = nullptr;
    // pmj02bn's sequences 1..4 for the 2D dimensions: only their first spp points (rounded up to a power
    // of two) are ever used, and a pmj02 sequence's prefix does not depend on its length.
    std::array<std::vector<pmj02::FixedPoint2>, kPmjSets - 1> sets;
    std::vector<Point2f> pmj_pixel_samples; // pmj02bn: pixel (x, y) of the tile, sample i at
                                            // ((y tile + x) spp + i)
};

Sampler::Sampler(SamplerKind kind, int samples_per_pixel, uint64_t seed, const SamplerSettings& settings)
    : kind_(kind), spp_(std::max(1, samples_per_pixel)), seed_(seed) {
    randomization_ = settings.randomization.value_or(
        kind == SamplerKind::halton ? Randomization::permute_digits : Randomization::fast_owen);
    Point2i res = settings.resolution;
    if (res.x <= 0 || res.y <= 0) res = {kMaxHaltonResolution, kMaxHaltonResolution};
    switch (kind) {
    case SamplerKind::independent:
        break;
    case SamplerKind::sobol:
        blocks_ = sampling_detail::sobol_blocks_vectorised();
        break;
    case SamplerKind::zsobol: {
        // Sample indices of a pixel: spp rounded up to a power of two (pbrt-v4 rounds down, which lets a
        // pixel's last samples run into the next pixel's indices).
        log2_spp_ = ceil_log2(spp_);
        base4_digits_ = ceil_log2(std::max(res.x, res.y)) + (log2_spp_ + 1) / 2;
        break;
    }
    case SamplerKind::paddedsobol:
        break;
    case SamplerKind::halton: {
        if (randomization_ == Randomization::fast_owen)
            throw Error(
                "the halton sampler has no \"fastowen\" randomization (use permutedigits, owen or none)");
        // Scales 2^j and 3^k covering the image (up to 128 pixels): the first two dimensions' digits below
        // them select the pixel.
        for (int i = 0; i < 2; ++i) {
            const int base = i == 0 ? 2 : 3, extent = std::min(i == 0 ? res.x : res.y, kMaxHaltonResolution);
            while (halton_scale_[i] < extent) halton_scale_[i] *= base, ++halton_exponent_[i];
        }
        halton_inverse_[0] = multiplicative_inverse(halton_scale_[1], halton_scale_[0]);
        halton_inverse_[1] = multiplicative_inverse(halton_scale_[0], halton_scale_[1]);
        if (randomization_ == Randomization::permute_digits) {
            auto t = std::make_shared<SamplerTables>();
            t->digit_permutations = make_digit_permutations(seed);
            tables_ = std::move(t);
        }
        break;
    }
    case SamplerKind::stratified: {
        x_samples_ = settings.x_samples, y_samples_ = settings.y_samples;
        jitter_ = settings.jitter;
        if (x_samples_ <= 0 || y_samples_ <= 0 || x_samples_ * y_samples_ != spp_) {
            int div = int(std::sqrt(double(spp_)));
            while (spp_ % div) --div;
            x_samples_ = spp_ / div, y_samples_ = div;
        }
        break;
    }
    case SamplerKind::pmj02bn: {
        if (spp_ > kPmjPoints)
            throw Error(fmt::format("the pmj02bn sampler takes at most {} samples per pixel", kPmjPoints));
        auto t = std::make_shared<SamplerTables>();
        t->pmj = &pmj02_data();
        // A tile of pmj_tile_^2 pixels shares sequence 0: its 2^16 points, sorted into the pixels by their
        // first digits, (rounded up to a power of 4) spp points per pixel, in the order of the sequence.
        const int log4 = (ceil_log2(spp_) + 1) / 2;
        const int log2_tile = 8 - log4;
        pmj_tile_ = 1 << log2_tile;
        std::vector<int> stored(size_t(pmj_tile_) * size_t(pmj_tile_), 0);
        t->pmj_pixel_samples.resize(stored.size() * size_t(spp_));
        for (int k = 1; k < kPmjSets; ++k)
            t->sets[size_t(k - 1)] = pmj02::generate(1 << ceil_log2(spp_), pmj_seed(k));
        for (const pmj02::FixedPoint2& p : t->pmj->pixel_sequence) {
            const uint32_t px = log2_tile ? p.x >> (32 - log2_tile) : 0u;
            const uint32_t py = log2_tile ? p.y >> (32 - log2_tile) : 0u;
            const size_t pixel = size_t(py) * size_t(pmj_tile_) + px;
            if (stored[pixel] == spp_) continue; // spp not a power of 4: the pixel's first spp points
            t->pmj_pixel_samples[pixel * size_t(spp_) + size_t(stored[pixel]++)] = {
                fixed_to_float(p.x << log2_tile), fixed_to_float(p.y << log2_tile)};
        }
        tables_ = std::move(t);
        break;
    }
    }
}

void Sampler::start_other(Point2i pixel) {
    pixel_ = pixel;
    dimension_ = 2;
    if (kind_ == SamplerKind::zsobol) {
        const uint32_t per_pixel = 1u << log2_spp_;
        const uint32_t round = index_ >> log2_spp_;
        const uint64_t morton = morton_2d(uint32_t(pixel.x), uint32_t(pixel.y));
        round_ = round, round_index_ = index_ & (per_pixel - 1);
        morton_index_ = (morton << log2_spp_) | round_index_;
        key_zsobol_cache();
        return;
    }
    if (kind_ == SamplerKind::halton) {
        // The index of the pixel's first sample: the i in [0, 2^j 3^k) with Φ_2(i) 2^j and Φ_3(i) 3^k
        // falling in pixel (x mod 128, y mod 128): the inverse radical inverses give i mod 2^j and i mod
        // 3^k, combined by the Chinese remainder theorem.
        const uint64_t stride = uint64_t(halton_scale_[0]) * uint64_t(halton_scale_[1]);
        uint64_t h = 0;
        if (stride > 1) {
            const int pm[2] = {
                ((pixel.x % kMaxHaltonResolution) + kMaxHaltonResolution) % kMaxHaltonResolution,
                ((pixel.y % kMaxHaltonResolution) + kMaxHaltonResolution) % kMaxHaltonResolution};
            for (int i = 0; i < 2; ++i) {
                const uint64_t residue =
                    inverse_radical_inverse(uint64_t(pm[i]), i == 0 ? 2 : 3, halton_exponent_[i]);
                h += residue * (stride / uint64_t(halton_scale_[i])) * uint64_t(halton_inverse_[i]);
            }
            h %= stride;
        }
        halton_index_ = h + uint64_t(index_) * stride;
        return;
    }
    round_ = index_ / uint32_t(spp_), round_index_ = index_ % uint32_t(spp_);
    pixel_hash_ = hash(seed_, pixel.x, pixel.y, round_);
}

void Sampler::key_zsobol_cache() {
    const uint64_t morton = morton_index_ >> log2_spp_;
    if (zsobol_cache_valid_ && morton == zsobol_cache_morton_ && round_ == zsobol_cache_round_) return;
    zsobol_cached_ = 0;
    zsobol_cache_valid_ = true;
    zsobol_cache_morton_ = morton;
    zsobol_cache_round_ = round_;
}

float Sampler::other_1d() {
    if (kind_ == SamplerKind::halton && dimension_ >= uint32_t(kPrimeCount)) dimension_ = 2;
    const uint32_t dim = dimension_++;
    switch (kind_) {
    case SamplerKind::zsobol:
        return zsobol_1d(dim);
    case SamplerKind::paddedsobol:
        return padded_1d(dim);
    case SamplerKind::halton:
        return halton_dimension(dim);
    case SamplerKind::stratified:
        return stratified_1d(dim);
    case SamplerKind::pmj02bn:
        return pmj02bn_1d(dim);
    default:
        return 0;
    }
}

void Sampler::pass_other(uint32_t n) {
    if (kind_ == SamplerKind::halton && dimension_ + n - 1 >= uint32_t(kPrimeCount)) dimension_ = 2;
    dimension_ += n;
}

Point2f Sampler::other_2d() {
    if (kind_ == SamplerKind::halton && dimension_ + 1 >= uint32_t(kPrimeCount)) dimension_ = 2;
    const uint32_t dim = dimension_;
    dimension_ += 2;
    switch (kind_) {
    case SamplerKind::zsobol:
        return zsobol_2d(dim);
    case SamplerKind::paddedsobol:
        return padded_2d(dim);
    case SamplerKind::halton:
        return {halton_dimension(dim), halton_dimension(dim + 1)};
    case SamplerKind::stratified:
        return stratified_2d(dim);
    case SamplerKind::pmj02bn:
        return pmj02bn_2d(dim);
    default:
        return {0, 0};
    }
}

Point2f Sampler::other_pixel_2d() {
    switch (kind_) {
    case SamplerKind::zsobol:
        return zsobol_2d(0);
    case SamplerKind::paddedsobol:
        return padded_2d(0);
    case SamplerKind::halton:
        // The digits of the first two dimensions below the scales chose the pixel; the rest is the
        // position inside it: Φ_2(i >> j) and Φ_3(i / 3^k).
        return {radical_inverse(0, halton_index_ >> halton_exponent_[0]),
                radical_inverse(1, halton_index_ / uint64_t(halton_scale_[1]))};
    case SamplerKind::stratified:
        return stratified_2d(0);
    case SamplerKind::pmj02bn: {
        if (round_ > 0) return pmj02bn_2d(0);
        const int px = pixel_.x & (pmj_tile_ - 1), py = pixel_.y & (pmj_tile_ - 1);
        return tables_
            ->pmj_pixel_samples[(size_t(py) * size_t(pmj_tile_) + size_t(px)) * size_t(spp_) + round_index_];
    }
    default:
        return {0, 0};
    }
}

// zsobol (Ahmed & Wonka 2020, as pbrt-v4's ZSobolSampler::GetSampleIndex): the Morton index's base-4
// digits, from the most significant down, each replaced by one of the 24 permutations of {0,1,2,3} chosen
// by a hash of the digits above it and the dimension; an odd log2 spp leaves a lowest single bit, flipped
// by a hashed bit. Pixels sharing the digits above share a permutation, so a block of 4^k pixels takes
// the 4^k spp consecutive indices of one Sobol block: stratified over the block.
//
// The digits above the pixel's sample bits depend only on (pixel, dimension, round): they are computed once
// per pixel for the first kZSobolCachedDimensions dimensions and kept while the render loop takes the
// pixel's other samples (a pure function cached, so the values are the same in any order).
uint64_t Sampler::zsobol_index(uint32_t dim) {
    const uint64_t key = mix_bits(seed_ ^ (uint64_t(dim) * kGolden) ^ (uint64_t(round_) << 40));
    const bool odd = log2_spp_ & 1;
    // Digit i covers bits [2i - odd, 2i - odd + 1]; digits from first_pixel_digit up hold pixel bits only.
    const int first_pixel_digit = (log2_spp_ + 1) / 2;
    auto permuted_digit = [&](int i) {
        const int shift = 2 * i - (odd ? 1 : 0);
        const uint64_t digit = (morton_index_ >> shift) & 3u;
        const uint64_t above = shift + 2 >= 64 ? 0 : morton_index_ >> (shift + 2);
        const uint32_t p = uint32_t(mix_bits(above ^ key) >> 32) % 24u;
        return uint64_t(kBase4Permutations[p][digit]) << shift;
    };
    uint64_t index = 0;
    if (dim < kZSobolCachedDimensions && (zsobol_cached_ >> dim) & 1u) {
        index = zsobol_pixel_digits_[dim];
    } else {
        for (int i = base4_digits_ - 1; i >= first_pixel_digit; --i) index |= permuted_digit(i);
        if (dim < kZSobolCachedDimensions) {
            zsobol_pixel_digits_[dim] = index;
            zsobol_cached_ |= uint64_t(1) << dim;
        }
    }
    for (int i = std::min(first_pixel_digit, base4_digits_) - 1; i >= (odd ? 1 : 0); --i)
        index |= permuted_digit(i);
    if (odd) index |= (morton_index_ & 1u) ^ (mix_bits((morton_index_ >> 1) ^ key) & 1u);
    return index;
}

float Sampler::zsobol_1d(uint32_t dim) {
    const uint32_t i = uint32_t(zsobol_index(dim));
    const uint64_t h = mix_bits(seed_ + (uint64_t(dim) + 1) * kGolden + (uint64_t(round_) << 32));
    return bits_to_unit_float(scramble_base2(sobol_dim0(i), uint32_t(h), randomization_));
}

Point2f Sampler::zsobol_2d(uint32_t dim) {
    const uint32_t i = uint32_t(zsobol_index(dim)); // bits above 32 do not reach a 32-bit fraction
    const uint64_t h = mix_bits(seed_ + (uint64_t(dim) + 1) * kGolden + (uint64_t(round_) << 32));
    return {bits_to_unit_float(scramble_base2(sobol_dim0(i), uint32_t(h), randomization_)),
            bits_to_unit_float(scramble_base2(sobol_dim1(i), uint32_t(h >> 32), randomization_))};
}

float Sampler::padded_1d(uint32_t dim) const {
    const uint64_t h = dimension_hash(pixel_hash_, dim);
    const uint32_t i = permutation_element(round_index_, uint32_t(spp_), uint32_t(h));
    return bits_to_unit_float(scramble_base2(sobol_dim0(i), uint32_t(h >> 32), randomization_));
}

Point2f Sampler::padded_2d(uint32_t dim) const {
    const uint64_t h = dimension_hash(pixel_hash_, dim), h2 = mix_bits(h);
    const uint32_t i = permutation_element(round_index_, uint32_t(spp_), uint32_t(h));
    return {bits_to_unit_float(scramble_base2(sobol_dim0(i), uint32_t(h2), randomization_)),
            bits_to_unit_float(scramble_base2(sobol_dim1(i), uint32_t(h2 >> 32), randomization_))};
}

float Sampler::halton_dimension(uint32_t dim) const {
    switch (randomization_) {
    case Randomization::permute_digits:
        return scrambled_radical_inverse(tables_->digit_permutations[dim], halton_index_);
    case Randomization::owen:
        return owen_scrambled_radical_inverse(int(dim), halton_index_,
                                              mix_bits(seed_ ^ (uint64_t(dim) * kGolden)));
    default:
        return radical_inverse(int(dim), halton_index_);
    }
}

// stratified: sample i's stratum is element i of a permutation of [0, spp) per (pixel, dimension); the
// jitter a hash of (pixel, dimension, i), so any dimension can be asked for in any order.
float Sampler::stratified_1d(uint32_t dim) const {
    const uint64_t h = dimension_hash(pixel_hash_, dim);
    const uint32_t stratum = permutation_element(round_index_, uint32_t(spp_), uint32_t(h));
    const float delta = jitter_ ? bits_to_unit_float(uint32_t(mix_bits(h ^ round_index_))) : 0.5f;
    return std::min((float(stratum) + delta) / float(spp_), kOneMinusEpsilon);
}

Point2f Sampler::stratified_2d(uint32_t dim) const {
    const uint64_t h = dimension_hash(pixel_hash_, dim);
    const uint32_t stratum = permutation_element(round_index_, uint32_t(spp_), uint32_t(h));
    const uint64_t j = mix_bits(h ^ round_index_);
    const float dx = jitter_ ? bits_to_unit_float(uint32_t(j)) : 0.5f;
    const float dy = jitter_ ? bits_to_unit_float(uint32_t(j >> 32)) : 0.5f;
    const uint32_t sx = stratum % uint32_t(x_samples_), sy = stratum / uint32_t(x_samples_);
    return {std::min((float(sx) + dx) / float(x_samples_), kOneMinusEpsilon),
            std::min((float(sy) + dy) / float(y_samples_), kOneMinusEpsilon)};
}

// The blue-noise value of this pixel for a dimension: tile dim mod 8 (so the two coordinates of a 2D
// dimension come from different tiles), shifted toroidally and in value by a hash of (seed, dimension).
float Sampler::blue_noise(uint32_t dim) const {
    constexpr int S = pmj02::kBlueNoiseSize;
    const uint64_t k = mix_bits(seed_ ^ ((uint64_t(dim) + 1) * kGolden));
    const int x = (pixel_.x + int(k & (S - 1))) & (S - 1), y = (pixel_.y + int((k >> 8) & (S - 1))) & (S - 1);
    const std::vector<float>& tile = tables_->pmj->blue_noise[dim % kBlueNoiseTiles];
    float v = tile[size_t(y * S + x)] + bits_to_unit_float(uint32_t(k >> 32));
    return v >= 1 ? v - 1 : v;
}

float Sampler::pmj02bn_1d(uint32_t dim) const {
    const uint64_t h = dimension_hash(pixel_hash_, dim);
    const uint32_t i = permutation_element(round_index_, uint32_t(spp_), uint32_t(h));
    return std::min((float(i) + blue_noise(dim)) / float(spp_), kOneMinusEpsilon);
}

Point2f Sampler::pmj02bn_2d(uint32_t dim) const {
    // Dimension pairs 0..4 take sequences 0..4 in order (every pixel the same points, rotated by its blue
    // noise); later pairs, and later rounds, a permutation of the pixel's indices.
    const uint32_t instance = dim / 2;
    uint32_t i = round_index_;
    if (instance >= uint32_t(kPmjSets) || round_ > 0)
        i = permutation_element(i, uint32_t(spp_), uint32_t(dimension_hash(pixel_hash_, dim)));
    const uint32_t set = instance % kPmjSets;
    const pmj02::FixedPoint2 p = set == 0 ? tables_->pmj->pixel_sequence[i] : tables_->sets[set - 1][i];
    float x = fixed_to_float(p.x) + blue_noise(dim), y = fixed_to_float(p.y) + blue_noise(dim + 1);
    if (x >= 1) x -= 1;
    if (y >= 1) y -= 1;
    return {std::min(x, kOneMinusEpsilon), std::min(y, kOneMinusEpsilon)};
}

} // namespace illum

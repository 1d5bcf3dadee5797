// Deterministic per-pixel samplers (DESIGN.md §3): the numbers of a pixel sample depend only on
// (seed, pixel, sample index, dimension), never on which thread renders the pixel or in which order, so an
// image is reproducible for any thread count and tile order.
//
// Dimensions: start_pixel_sample() resets the dimension counter. get_pixel_2d() always returns dimension 0
// (the film-plane offset), wherever it is called; each get_1d() / get_2d() call then takes the next
// dimension (1, 2, ...), one per call whether 1D or 2D.
//
// Kinds (pbrt-v4's samplers, docs/scenes.md says where they differ):
//  - independent: a PCG32 stream seeded by hash(seed, pixel, sample index).
//  - sobol: padded, Owen-scrambled Sobol after B. Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4)
//    2020. Every dimension (1D) or dimension pair (2D) uses the first one or two Sobol dimensions with the
//    sample index shuffled by a nested uniform (Owen) scramble seeded by hash(seed, pixel, dimension), and
//    each output coordinate Owen-scrambled with its own hashed seed. The index shuffle maps the first 2^k
//    indices onto one aligned block of 2^k Sobol points, so for every k the first 2^k samples of a pixel
//    are stratified (a (0, k, 2)-net in 2D), and dimensions are decorrelated from each other.
//  - zsobol: pbrt-v4's ZSobolSampler (A. Ahmed, P. Wonka, "Screen-Space Blue-Noise Diffusion of Monte
//    Carlo Sampling Error via Hierarchical Ordering of Pixels", SIGGRAPH Asia 2020): one Sobol (0,2)
//    sequence over the whole image, pixel p taking the indices (Morton(p) << log2 spp) + i, with the
//    base-4 digits of that index permuted by a hash of the digits above and of the dimension, and the
//    values scrambled per dimension ("randomization"). Neighbouring pixels share strata of one sequence,
//    so the error is blue noise in screen space.
//  - paddedsobol: pbrt-v4's PaddedSobolSampler: per (pixel, dimension) a hashed permutation of [0, spp)
//    picks the index into the first one or two Sobol dimensions, values scrambled ("randomization").
//  - halton: pbrt-v4's HaltonSampler: radical inverses in the d-th prime base of one global index; the
//    pixel is found from the first two dimensions (bases 2 and 3, scaled by 2^j, 3^k >= the resolution up
//    to 128) through the Chinese remainder theorem; digits permuted or Owen-scrambled.
//  - pmj02bn: pbrt-v4's PMJ02BNSampler: progressive multi-jittered (0,2) sequences (pmj02.h) for the
//    pixel offset (a 2^k x 2^k tile of pixels shares one sequence) and the 2D dimensions, Cranley-Patterson
//    rotated per pixel by a blue-noise tile; 1D dimensions are stratified with blue-noise jitter.
//  - stratified: pbrt-v4's StratifiedSampler: x_samples x y_samples strata in 2D (spp in 1D), the
//    stratum of sample i a hashed permutation per (pixel, dimension), jittered within or centred.
// The low-discrepancy kinds take indices beyond spp (time-budget renders) as further rounds of spp,
// each round randomised by its own hash.
//
// Nothing is allocated per sample; a Sampler is a small value to copy into each thread.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include "illum/math/rng.h"
#include "illum/math/vector.h"
#include "illum/render/sobol_block.h"

namespace illum {

enum class SamplerKind : uint8_t { independent, sobol, zsobol, paddedsobol, halton, pmj02bn, stratified };

std::string_view sampler_kind_name(SamplerKind kind);
// "independent" / "random", "sobol" / "owen-sobol", "zsobol", "paddedsobol", "halton", "pmj02bn" or
// "stratified"; nullopt otherwise.
std::optional<SamplerKind> parse_sampler_kind(std::string_view name);

// pbrt-v4's "randomization" of the Sobol and Halton samplers: none, a random digit permutation per digit
// position ("permutedigits"; in base 2 an XOR, a random digital shift), Burley's hashed approximation of
// Owen scrambling ("fastowen") or the exact nested scramble ("owen").
enum class Randomization : uint8_t { none, permute_digits, fast_owen, owen };
std::string_view randomization_name(Randomization r);
std::optional<Randomization> parse_randomization(std::string_view name);

// What a scene's Sampler directive sets besides the kind, the sample count and the seed.
struct SamplerSettings {
    // nullopt: the kind's default (halton: permute_digits; zsobol, paddedsobol: fast_owen).
    std::optional<Randomization> randomization;
    bool jitter = true;               // stratified: jitter within the stratum (else its centre)
    int x_samples = 0, y_samples = 0; // stratified: strata; used when their product is spp, else spp is
                                      // factored as pbrt-v4 does for --spp (y the largest divisor <= sqrt)
    Point2i resolution{0, 0};         // the film's; zsobol's Morton digits, halton's pixel scales
                                      // (0: 128 x 128)
};

// The tables a sampler shares between its copies (halton's digit permutations, pmj02bn's pixel samples).
struct SamplerTables;

class Sampler {
public:
    // Two blocks of sobol draws (block_draw): id[current] is at hand, the other computed ahead.
    struct DrawBlocks {
        static constexpr uint32_t kNone = ~0u;
        uint32_t id[2] = {kNone, kNone};
        uint32_t current = 0;
        float x[2][sampling_detail::kSobolBlock] = {}, y[2][sampling_detail::kSobolBlock] = {};
    };

    // Throws illum::Error for settings the kind cannot take (pmj02bn beyond 65536 spp).
    Sampler(SamplerKind kind, int samples_per_pixel, uint64_t seed = 0, const SamplerSettings& settings = {});

    SamplerKind kind() const { return kind_; }
    int samples_per_pixel() const { return spp_; }
    uint64_t seed() const { return seed_; }

    void start_pixel_sample(Point2i pixel, int sample_index) {
        index_ = uint32_t(sample_index);
        dimension_ = 1;
        if (kind_ == SamplerKind::independent) {
            uint64_t h = hash(seed_, pixel.x, pixel.y, sample_index);
            rng_.set_sequence(h, mix_bits(h));
            pixel_rng_ = rng_;
            rng_.advance(2); // the first two numbers belong to get_pixel_2d()
        } else if (kind_ == SamplerKind::sobol) {
            pixel_hash_ = hash(seed_, pixel.x, pixel.y);
            reversed_index_ = sampling_detail::reverse_bits(index_);
            if (blocks_) start_blocks();
        } else {
            start_other(pixel);
        }
    }

    float get_1d() {
        if (kind_ == SamplerKind::independent) return rng_.uniform_float();
        if (kind_ == SamplerKind::sobol) return blocks_ ? block_draw(dimension_++).x : sobol_1d(dimension_++);
        return other_1d();
    }

    Point2f get_2d() {
        if (kind_ == SamplerKind::independent) {
            float x = rng_.uniform_float();
            return {x, rng_.uniform_float()};
        }
        if (kind_ == SamplerKind::sobol) return blocks_ ? block_draw(dimension_++) : sobol_2d(dimension_++);
        return other_2d();
    }

    // get_1d() / get_2d() for a caller that reads the draw only when `read`: a draw a model ignores (a
    // one-lobe BSDF's lobe choice, a pinhole camera's lens point) is not computed, its dimensions passed
    // over so that the sequence afterwards is the same, and 0 returned. The dimension-indexed kinds skip
    // the work (for Owen-scrambled Sobol' a draw costs several times a PCG32 number); the independent kind
    // draws as always, keeping its stream in step.
    float get_1d_if(bool read) {
        if (read || kind_ == SamplerKind::independent) return get_1d();
        pass_dimensions(1);
        return 0;
    }
    Point2f get_2d_if(bool read) {
        if (read || kind_ == SamplerKind::independent) return get_2d();
        pass_dimensions(2);
        return {0, 0};
    }

    // Where a pixel sample has got to, for resuming it later: the render loop starts the samples of a
    // camera-ray packet one after another and continues each once the packet is traced. zsobol's cache of
    // a pixel's digits is not part of it: resume() keeps the cache where it belongs to the resumed sample's
    // pixel and round, and empties it otherwise. sobol's blocks of draws are.
    struct Position {
        uint32_t index, dimension, reversed_index;
        uint64_t pixel_hash;
        PCG32 rng, pixel_rng;
        Point2i pixel;
        uint32_t round, round_index;
        uint64_t morton_index, halton_index;
        DrawBlocks blocks;
    };
    Position position() const {
        return {index_,       dimension_,    reversed_index_, pixel_hash_,
                rng_,         pixel_rng_,    pixel_,          round_,
                round_index_, morton_index_, halton_index_,   blocks_ ? draws_ : DrawBlocks{}};
    }
    void resume(const Position& p) {
        index_ = p.index;
        dimension_ = p.dimension;
        reversed_index_ = p.reversed_index;
        pixel_hash_ = p.pixel_hash;
        rng_ = p.rng;
        pixel_rng_ = p.pixel_rng;
        pixel_ = p.pixel;
        round_ = p.round;
        round_index_ = p.round_index;
        morton_index_ = p.morton_index;
        halton_index_ = p.halton_index;
        if (blocks_) draws_ = p.blocks;
        if (kind_ == SamplerKind::zsobol) key_zsobol_cache();
    }

    Point2f get_pixel_2d() {
        if (kind_ == SamplerKind::independent) {
            PCG32 r = pixel_rng_;
            float x = r.uniform_float();
            return {x, r.uniform_float()};
        }
        if (kind_ == SamplerKind::sobol) {
            // Dimension 0 is lane 0 of block 0, computed when the sample started.
            if (blocks_)
                for (uint32_t slot : {draws_.current, draws_.current ^ 1})
                    if (draws_.id[slot] == 0) return {draws_.x[slot][0], draws_.y[slot][0]};
            return sobol_2d(0);
        }
        return other_pixel_2d();
    }

private:
    // Dimension dim of sample index_ (sobol_block.h): two chains of hashing, three bit reversals for 2D and
    // two for 1D.
    float sobol_1d(uint32_t dim) const {
        return sampling_detail::sobol_owen_1d(pixel_hash_, reversed_index_, dim);
    }
    Point2f sobol_2d(uint32_t dim) const {
        return sampling_detail::sobol_owen_2d(pixel_hash_, reversed_index_, dim);
    }
    // The same from the block of eight dimensions that holds dim (block b: dimensions 8b .. 8b + 7),
    // computed in vector lanes (sobol_block.h); the value does not depend on the way, as the block's lanes
    // are the scalar draws. A block takes about 110 cycles from its seeds to its values, a chain of
    // dependent multiplications that stalls the path wherever it is computed: the stores of its values hold
    // up the instructions behind them. Blocks 0 and 1 are computed when the sample starts (the pixel's
    // offset, dimension 0, is block 0's first draw), side by side, and in a camera-ray packet while the
    // packet's other samples start; a path of two bounces draws from both (on the Cornell box, most paths).
    // Block b + 1 >= 2 is computed when the path draws from the second half of block b, and not for the
    // paths that end before.
    Point2f block_draw(uint32_t dim) {
        const uint32_t b = dim / sampling_detail::kSobolBlock, k = dim % sampling_detail::kSobolBlock;
        if (b != draws_.id[draws_.current]) enter_block(b);
        const uint32_t c = draws_.current;
        if (k >= kAheadFrom && draws_.id[c ^ 1] != b + 1) compute_block(b + 1, c ^ 1);
        return {draws_.x[c][k], draws_.y[c][k]};
    }
    void start_blocks();
    void enter_block(uint32_t b);
    // Block b's values into draws_ slot `slot`, from the pixel's seeds (kept for the first kSeedBlocks blocks
    // while the samples stay in one pixel).
    void compute_block(uint32_t b, uint32_t slot);

    // Moves past the dimensions a 1D (n = 1) or 2D (n = 2) draw would take, as get_1d() / get_2d() advance
    // them (sobol: one either way; halton: wrapping past its primes).
    void pass_dimensions(uint32_t n) {
        if (kind_ == SamplerKind::sobol)
            ++dimension_;
        else
            pass_other(n);
    }
    void pass_other(uint32_t n);

    // The kinds after sobol (sampler.cpp). Their dimensions: the pixel offset is dimension pair (0, 1)
    // wherever it is asked for; get_1d() then takes dimension 2, 3, ... one each, get_2d() two each.
    void start_other(Point2i pixel);
    // zsobol: empties the cache of pixel digits unless it holds those of the current pixel and round.
    void key_zsobol_cache();
    float other_1d();
    Point2f other_2d();
    Point2f other_pixel_2d();
    float zsobol_1d(uint32_t dim);
    Point2f zsobol_2d(uint32_t dim);
    float padded_1d(uint32_t dim) const;
    Point2f padded_2d(uint32_t dim) const;
    float halton_dimension(uint32_t dim) const;
    float stratified_1d(uint32_t dim) const;
    Point2f stratified_2d(uint32_t dim) const;
    float pmj02bn_1d(uint32_t dim) const;
    Point2f pmj02bn_2d(uint32_t dim) const;
    float blue_noise(uint32_t dim) const;
    uint64_t zsobol_index(uint32_t dim);

    SamplerKind kind_;
    int spp_;
    uint64_t seed_;
    uint32_t index_ = 0, dimension_ = 1;
    uint32_t reversed_index_ = 0; // sobol: reverse_bits(index_)
    uint64_t pixel_hash_ = 0;
    PCG32 rng_, pixel_rng_;
    // sobol, where blocks are computed in vector lanes (blocks_): the block of draws at hand and the next.
    bool blocks_ = false;
    DrawBlocks draws_;
    static constexpr uint32_t kSeedBlocks = 8;
    static constexpr uint32_t kAheadFrom = 4; // the draw of a block from which the next one is computed
    uint64_t seeds_pixel_hash_ = 0; // the pixel whose seeds seeds_ holds (bit b of seeds_valid_: block b's)
    uint32_t seeds_valid_ = 0;
    sampling_detail::SobolBlockSeeds seeds_[kSeedBlocks] = {};

    // The other kinds' state.
    Randomization randomization_ = Randomization::fast_owen;
    Point2i pixel_{0, 0};
    uint32_t round_ = 0,
             round_index_ = 0; // index_ = round_ * spp + round_index_ (zsobol: spp rounded up to 2^k)
    uint64_t morton_index_ = 0, halton_index_ = 0;
    int log2_spp_ = 0, base4_digits_ = 0; // zsobol
    // zsobol: the permuted pixel digits of the current pixel's first dimensions (bit d of zsobol_cached_:
    // dimension d's are there).
    static constexpr uint32_t kZSobolCachedDimensions = 32;
    uint64_t zsobol_cached_ = 0;
    bool zsobol_cache_valid_ = false;
    uint64_t zsobol_cache_morton_ = 0; // the pixel (Morton index) and round the cache holds digits of
    uint32_t zsobol_cache_round_ = 0;
    uint64_t zsobol_pixel_digits_[kZSobolCachedDimensions] = {};
    int halton_scale_[2] = {1, 1}, halton_exponent_[2] = {0, 0};
    int64_t halton_inverse_[2] = {0, 0};
    int x_samples_ = 1, y_samples_ = 1; // stratified
    bool jitter_ = true;
    int pmj_tile_ = 1; // pmj02bn: pixels per side sharing one sequence
    std::shared_ptr<const SamplerTables> tables_;
};

} // namespace illum

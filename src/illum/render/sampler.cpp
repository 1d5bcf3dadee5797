#include "illum/render/sampler.h"

#include <array>

namespace illum {

std::string_view sampler_kind_name(SamplerKind kind) {
    switch (kind) {
    case SamplerKind::independent:
        return "independent";
    case SamplerKind::sobol:
        return "sobol";
    case SamplerKind::zsobol:
        return "zsobol";
    case SamplerKind::paddedsobol:
        return "paddedsobol";
    case SamplerKind::halton:
        return "halton";
    case SamplerKind::pmj02bn:
        return "pmj02bn";
    case SamplerKind::stratified:
        return "stratified";
    }
    return "unknown";
}

std::optional<SamplerKind> parse_sampler_kind(std::string_view name) {
    if (name == "independent" || name == "random") return SamplerKind::independent;
    if (name == "sobol" || name == "owen-sobol") return SamplerKind::sobol;
    for (SamplerKind k : {SamplerKind::zsobol, SamplerKind::paddedsobol, SamplerKind::halton,
                          SamplerKind::pmj02bn, SamplerKind::stratified})
        if (name == sampler_kind_name(k)) return k;
    return std::nullopt;
}

std::string_view randomization_name(Randomization r) {
    switch (r) {
    case Randomization::none:
        return "none";
    case Randomization::permute_digits:
        return "permutedigits";
    case Randomization::fast_owen:
        return "fastowen";
    case Randomization::owen:
        return "owen";
    }
    return "unknown";
}

std::optional<Randomization> parse_randomization(std::string_view name) {
    for (Randomization r :
         {Randomization::none, Randomization::permute_digits, Randomization::fast_owen, Randomization::owen})
        if (name == randomization_name(r)) return r;
    return std::nullopt;
}

namespace sampling_detail {

namespace {

// Dimension 1's direction numbers: v_0 = 2^31, v_i = v_{i-1} ^ (v_{i-1} >> 1).
constexpr std::array<uint32_t, 32> kSobolDim1Directions = [] {
    std::array<uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int i = 1; i < 32; ++i) v[i] = v[i - 1] ^ (v[i - 1] >> 1);
    return v;
}();

constexpr uint32_t reverse_bits_constexpr(uint32_t v) {
    uint32_t r = 0;
    for (int b = 0; b < 32; ++b) r |= ((v >> b) & 1u) << (31 - b);
    return r;
}

// A GF(2)-linear map of 32-bit words by byte: table[b][k] = XOR of column(8b + j) over the set bits j of
// the byte k, column(i) being the image of bit i.
template <class Column>
constexpr std::array<std::array<uint32_t, 256>, 4> byte_tables(Column column) {
    std::array<std::array<uint32_t, 256>, 4> t{};
    for (int b = 0; b < 4; ++b)
        for (int k = 0; k < 256; ++k) {
            uint32_t r = 0;
            for (int j = 0; j < 8; ++j)
                if (k & (1 << j)) r ^= column(8 * b + j);
            t[b][k] = r;
        }
    return t;
}

// Bit i of the index contributes v_i.
constexpr auto kSobolDim1 = byte_tables([](int i) { return kSobolDim1Directions[std::size_t(i)]; });
// Bit i of reverse(index) is bit 31 - i of the index, which contributes v_{31-i}; the sum reversed.
constexpr auto kSobolDim1Reversed =
    byte_tables([](int i) { return reverse_bits_constexpr(kSobolDim1Directions[std::size_t(31 - i)]); });

} // namespace

uint32_t sobol_dim1(uint32_t index) {
    return kSobolDim1[0][index & 0xff] ^ kSobolDim1[1][(index >> 8) & 0xff] ^
           kSobolDim1[2][(index >> 16) & 0xff] ^ kSobolDim1[3][index >> 24];
}

uint32_t sobol_dim1_reversed(uint32_t r) {
    return kSobolDim1Reversed[0][r & 0xff] ^ kSobolDim1Reversed[1][(r >> 8) & 0xff] ^
           kSobolDim1Reversed[2][(r >> 16) & 0xff] ^ kSobolDim1Reversed[3][r >> 24];
}

} // namespace sampling_detail

void Sampler::compute_block(uint32_t b, uint32_t slot) {
    using namespace sampling_detail;
    if (seeds_pixel_hash_ != pixel_hash_) {
        seeds_pixel_hash_ = pixel_hash_;
        seeds_valid_ = 0;
    }
    SobolBlockSeeds scratch;
    const SobolBlockSeeds* seeds = &scratch;
    if (b < kSeedBlocks) {
        seeds = &seeds_[b];
        if (!(seeds_valid_ & (1u << b))) {
            sobol_block_seeds(pixel_hash_, b * kSobolBlock, &seeds_[b]);
            seeds_valid_ |= 1u << b;
        }
    } else {
        sobol_block_seeds(pixel_hash_, b * kSobolBlock, &scratch);
    }
    sobol_block(*seeds, reversed_index_, draws_.x[slot], draws_.y[slot]);
    draws_.id[slot] = b;
}

void Sampler::start_blocks() {
    draws_.current = 0;
    compute_block(0, 0);
    compute_block(1, 1);
}

void Sampler::enter_block(uint32_t b) {
    uint32_t& c = draws_.current;
    if (draws_.id[c ^ 1] == b)
        c ^= 1;
    else // not computed ahead: a draw past the next block (pass_dimensions) or a resumed old position
        compute_block(b, c);
}

} // namespace illum

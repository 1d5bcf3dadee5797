#include "illum/render/sampler.h"

#include <array>

namespace illum {

std::string_view sampler_kind_name(SamplerKind kind) {
    switch (kind) {
    case SamplerKind::independent:
        return "independent";
    case SamplerKind::sobol:
        return "sobol";
    }
    return "unknown";
}

std::optional<SamplerKind> parse_sampler_kind(std::string_view name) {
    if (name == "independent" || name == "random") return SamplerKind::independent;
    if (name == "sobol" || name == "zsobol" || name == "owen-sobol") return SamplerKind::sobol;
    return std::nullopt;
}

namespace sampling_detail {

namespace {

// table[b][k] = XOR of the direction numbers v_{8b + j} over the set bits j of the byte k.
constexpr std::array<std::array<uint32_t, 256>, 4> make_sobol_dim1_tables() {
    std::array<uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int i = 1; i < 32; ++i) v[i] = v[i - 1] ^ (v[i - 1] >> 1);
    std::array<std::array<uint32_t, 256>, 4> t{};
    for (int b = 0; b < 4; ++b)
        for (int k = 0; k < 256; ++k) {
            uint32_t r = 0;
            for (int j = 0; j < 8; ++j)
                if (k & (1 << j)) r ^= v[8 * b + j];
            t[b][k] = r;
        }
    return t;
}

constexpr auto kSobolDim1 = make_sobol_dim1_tables();

} // namespace

uint32_t sobol_dim1(uint32_t index) {
    return kSobolDim1[0][index & 0xff] ^ kSobolDim1[1][(index >> 8) & 0xff] ^
           kSobolDim1[2][(index >> 16) & 0xff] ^ kSobolDim1[3][index >> 24];
}

} // namespace sampling_detail

} // namespace illum

// The embedded tables: tools/rgb2spec_opt.cpp writes one file per colour space into the build tree
// (cmake/rgb2spec.cmake), and the assembler's .incbin puts each in .rodata under a symbol of its own, so
// the tables cost no start-up time and no file at run time.
#include "illum/radiometry/rgb_to_spectrum.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#ifndef ILLUM_RGB2SPEC_DIR
#error "ILLUM_RGB2SPEC_DIR (the generated tables' folder) must be defined by the build"
#endif

#define ILLUM_EMBED(symbol, file)                                                                            \
    asm(".section .rodata\n"                                                                                 \
        ".balign 64\n"                                                                                       \
        ".global " #symbol "\n"                                                                              \
        ".type " #symbol ", @object\n" #symbol ":\n"                                                         \
        ".incbin \"" ILLUM_RGB2SPEC_DIR "/" file "\"\n"                                                      \
        ".global " #symbol "_end\n" #symbol "_end:\n"                                                        \
        ".previous\n")

// In RGBColorSpace::index() order.
ILLUM_EMBED(illum_rgb2spec_srgb, "srgb.bin");
ILLUM_EMBED(illum_rgb2spec_rec2020, "rec2020.bin");
ILLUM_EMBED(illum_rgb2spec_aces2065_1, "aces2065-1.bin");
ILLUM_EMBED(illum_rgb2spec_dci_p3, "dci-p3.bin");

extern "C" {
extern const unsigned char illum_rgb2spec_srgb[], illum_rgb2spec_srgb_end[];
extern const unsigned char illum_rgb2spec_rec2020[], illum_rgb2spec_rec2020_end[];
extern const unsigned char illum_rgb2spec_aces2065_1[], illum_rgb2spec_aces2065_1_end[];
extern const unsigned char illum_rgb2spec_dci_p3[], illum_rgb2spec_dci_p3_end[];
}

namespace illum {

namespace {

RGBToSpectrumTable view(const unsigned char* begin, const unsigned char* end, const char* name) {
    RGBToSpectrumFileHeader expected, header;
    std::size_t size =
        std::size_t(reinterpret_cast<std::uintptr_t>(end) - reinterpret_cast<std::uintptr_t>(begin));
    if (size >= sizeof header) std::memcpy(&header, begin, sizeof header);
    const int res = RGBToSpectrumTable::kResolution;
    std::size_t floats = std::size_t(res) + std::size_t(9) * res * res * res;
    if (size != sizeof header + floats * sizeof(float) ||
        std::memcmp(header.magic, expected.magic, sizeof header.magic) != 0 ||
        header.res != std::uint32_t(res) || header.floats != floats)
        throw std::logic_error(std::string("the embedded RGB-to-spectrum table of ") + name +
                               " is malformed");
    // The header is 16 bytes and the blob 64-byte aligned, so the floats are aligned.
    const float* data = reinterpret_cast<const float*>(begin + sizeof header);
    return {res, data, data + res};
}

} // namespace

const RGBToSpectrumTable& rgb_to_spectrum_table(int space_index) {
    static const RGBToSpectrumTable tables[RGBColorSpace::kCount] = {
        view(illum_rgb2spec_srgb, illum_rgb2spec_srgb_end, "srgb"),
        view(illum_rgb2spec_rec2020, illum_rgb2spec_rec2020_end, "rec2020"),
        view(illum_rgb2spec_aces2065_1, illum_rgb2spec_aces2065_1_end, "aces2065-1"),
        view(illum_rgb2spec_dci_p3, illum_rgb2spec_dci_p3_end, "dci-p3"),
    };
    return tables[space_index];
}

} // namespace illum

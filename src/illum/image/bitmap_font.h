// A 5 x 7 bitmap font (with two rows of descender) for the rasterised plots: printable ASCII, the Greek
// letters and the signs the plots write (θ φ ψ ρ α δ ε μ σ π ω η λ Ω Δ Σ ∫ √ ≤ ≥ ≈ ° · ² ± − ×). Drawn for
// illum; a code point it lacks shows as a hollow box.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace illum {

struct Glyph {
    // rows[r] bit (4 - c) set: the cell in row r (0 at the top; 6 rests on the baseline, 7 and 8 descend)
    // and column c (0 at the left) is ink.
    std::uint8_t rows[9] = {};
};

inline constexpr int kGlyphColumns = 5, kGlyphCapRows = 7, kGlyphRows = 9, kGlyphAdvance = 6;

const Glyph& glyph(char32_t code_point);
// The code points of UTF-8 text (an invalid byte becomes U+FFFD).
std::vector<char32_t> decode_utf8(const std::string& text);

} // namespace illum

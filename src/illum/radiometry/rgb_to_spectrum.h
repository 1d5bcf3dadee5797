// The RGB -> sigmoid-polynomial tables of Jakob & Hanika 2019 §5 and their lookup.
//
// Three tables per colour space, one for each component that is the largest (i = argmax rgb); each holds
// res³ entries of the three coefficients (in λ [nm], RGBSigmoidPolynomial) over
//   z = rgb_i on a grid z_k = smoothstep(smoothstep(k / (res-1))), smoothstep(t) = 3t² - 2t³, dense near
//     0 and 1 where the coefficients change fastest (dark colours, and bright saturated ones);
//   x = rgb_(i+1)%3 / z and y = rgb_(i+2)%3 / z on the grid h(x_j) = j / (res-1), h(x) = x (2 - 2x + x²),
//     twice as dense near 0 (a component near 0) as uniform.
// An RGB is looked up by trilinear interpolation of the coefficients (in z, h(x) and h(y)); an RGB
// with r + g + b > 3/2 as the negated polynomial of 1 - rgb (S(-x) = 1 - S(x)). The tables are computed by
// illum's own optimiser (sigmoid_fit.h) at build time (tools/rgb2spec_opt.cpp) and embedded in the library.
//
// Measured choices (sRGB round trip on 71³ points of [0, 0.98]³, tables without the generator's
// interpolation correction): z grids uniform 8.2e-3 (1162 points above 1e-3), smoothstep 1.5e-3 (48),
// smoothstep² 1.4e-3 (21), smoothstep³ 7.6e-3 (3612); resolutions 48: 4.0e-3, 64: 1.4e-3, 96: 7.7e-4
// (3.4x the 9.4 MB per space). 64 it is, with the correction bringing it to 6.5e-4.
// That layout with uniform x and y failed near white and at the saturated edges: over [0, 1]³ (73³) 0.0133
// at (0.986, 1, 1), 141 points above 1e-3. Looking up the brighter half through the complement left
// 1.34e-3 at (0.0139, 0, 1) (x's first cell at z = 1; 2 points above 1e-3). x and y nodes denser near 0
// too: g(t) = t ((1-a) + a t) (x = g(j / (res-1)), looked up by g⁻¹, a square root) with a = 0.3: 5.6e-4 on
// 73³ but 9.6e-4 at (0.0079, 0, 1) on 127³; a = 1/2: 3.4e-4 (73³), 3.8e-4 (145³); h above (as dense
// near 0, no square root): 3.4e-4 (73³), 3.6e-4 (145³), and the interior [0.02, 0.98]³ 3.3e-4 (was
// 6.9e-4). The lookup costs 19.5 ns cached instead of 13.9 (20.2 with g⁻¹).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "illum/radiometry/color_space.h"

namespace illum {

struct RGBToSpectrumTable {
    static constexpr int kResolution = 64;

    int res = 0;
    const float* z = nullptr;      // res grid values of the largest component
    const float* coeffs = nullptr; // [3 (argmax)][res (z)][res (y)][res (x)][3 (c0, c1, c2)]

    static double z_node(int k, int res) {
        auto smoothstep = [](double t) { return t * t * (3 - 2 * t); };
        return smoothstep(smoothstep(double(k) / (res - 1)));
    }
    // The x and y grid coordinate t = h(x) = x (2 - 2x + x²), nodes x_j = h⁻¹(j / (res-1)): h'(0) = 2 makes
    // the spacing 1/(2 (res-1)) near 0, where a component tends to 0 (saturated colours, whose coefficients
    // change fastest); h' = 2/3 at x = 2/3, h'(1) = 1. A cubic costs two FMAs, not a square root.
    static float xy_coordinate(float x) { return x * std::fma(x, x - 2, 2.0f); }
    static double xy_node(double t) { // h⁻¹ by bisection (h is increasing: h' = 3x² - 4x + 2 > 0)
        double lo = 0, hi = 1;
        for (int it = 0; it < 60; ++it) {
            double m = 0.5 * (lo + hi);
            (m * (2 - 2 * m + m * m) < t ? lo : hi) = m;
        }
        return 0.5 * (lo + hi);
    }
    static std::size_t offset(int i, int zi, int yi, int xi, int res) {
        return 3 * (((std::size_t(i) * res + zi) * res + yi) * res + xi);
    }

    // Grey r = g = b = v has the exact constant spectrum v: c0 = c1 = 0, c2 = S⁻¹(v) = (v - 1/2) / √(v (1-v))
    // (±∞ for white and black).
    static RGBSigmoidPolynomial grey(float v) {
        if (v <= 0) return {0, 0, -INFINITY};
        if (v >= 1) return {0, 0, INFINITY};
        return {0, 0, (v - 0.5f) / std::sqrt(v * (1 - v))};
    }

    RGBSigmoidPolynomial lookup(Color3 rgb) const {
        // Clamped to [0, 1] with NaN to 0 (std::clamp passes NaN through, which the index conversions below
        // must not see; an infinite emitter scaled by its own maximum gives inf / inf).
        auto unit = [](float v) { return v > 0 ? (v < 1 ? v : 1.0f) : 0.0f; };
        rgb = Color3(unit(rgb.r), unit(rgb.g), unit(rgb.b));
        if (rgb.r == rgb.g && rgb.g == rgb.b) return grey(rgb.r);
        // S(-x) = 1 - S(x), so -c has the spectrum 1 - s and, the illuminant being the white (1, 1, 1),
        // the colour 1 - rgb: the brighter half of the cube is looked up through its complement, and the
        // near-whites (an x and a y near 1 at z = 1, the coefficients' fastest change on those grids)
        // become near-blacks, on z's grid dense near 0. Selects, not a branch (random colours take
        // either side).
        bool bright = rgb.r + rgb.g + rgb.b > 1.5f;
        Color3 q(bright ? 1 - rgb.r : rgb.r, bright ? 1 - rgb.g : rgb.g, bright ? 1 - rgb.b : rgb.b);
        RGBSigmoidPolynomial p = lookup_table(q);
        float sign = bright ? -1.0f : 1.0f;
        return {sign * p.c0, sign * p.c1, sign * p.c2};
    }

    // The table's trilinear interpolation, without the complement (rgb in [0, 1]³, not grey).
    RGBSigmoidPolynomial lookup_table(Color3 rgb) const {
        int i = rgb.r >= rgb.g ? (rgb.r >= rgb.b ? 0 : 2) : (rgb.g >= rgb.b ? 1 : 2);
        float zv = rgb[i], inv = 1 / zv;
        float x = (res - 1) * xy_coordinate(rgb[(i + 1) % 3] * inv),
              y = (res - 1) * xy_coordinate(rgb[(i + 2) % 3] * inv);
        int xi = std::min(int(x), res - 2), yi = std::min(int(y), res - 2);
        // The last node at or below zv among z[0..res-2].
        int zi = int(std::upper_bound(z + 1, z + res - 1, zv) - z) - 1;
        float dx = x - xi, dy = y - yi, dz = (zv - z[zi]) / (z[zi + 1] - z[zi]);
        float c[3] = {0, 0, 0};
        for (int corner = 0; corner < 8; ++corner) {
            int ox = corner & 1, oy = (corner >> 1) & 1, oz = corner >> 2;
            float w = (ox ? dx : 1 - dx) * (oy ? dy : 1 - dy) * (oz ? dz : 1 - dz);
            const float* e = coeffs + offset(i, zi + oz, yi + oy, xi + ox, res);
            c[0] += w * e[0], c[1] += w * e[1], c[2] += w * e[2];
        }
        return {c[0], c[1], c[2]};
    }
};

// The generator's file (one per colour space, embedded by rgb_to_spectrum.cpp): this header, then the
// res z nodes and the coefficients as little-endian float, laid out as RGBToSpectrumTable says.
struct RGBToSpectrumFileHeader {
    char magic[8] = {'I', 'L', 'R', 'G', 'B', '2', 'S', '2'};
    std::uint32_t res = 0;
    std::uint32_t floats = 0; // res + 3 res³ · 3
};

// The embedded table of a named colour space (RGBColorSpace::index()).
const RGBToSpectrumTable& rgb_to_spectrum_table(int space_index);

} // namespace illum

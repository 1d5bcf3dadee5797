// Prefiltered environment maps for real-time image-based lighting, by the split-sum approximation
// (B. Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes):
//  - a mip chain of latitude-longitude maps, level i for roughness r_i = i / (levels - 1), each texel the
//    radiance convolved with the GGX lobe (α = r²) about its direction under N = V = R, importance
//    sampled by the GGX distribution of half vectors and weighted by N·L;
//  - the 2D table of the BRDF's scale and bias to F0, (A, B)(N·V, r), with Smith-Schlick G (k = α/2).
#pragma once

#include <vector>

#include "illum/envmap/environment_map.h"

namespace illum {

class Progress;

struct PrefilterOptions {
    int height = 128;  // rows of level 0 (its width is twice that)
    int levels = 6;    // roughness 0 .. 1 in equal steps; level i has height >> i rows (at least 4)
    int samples = 256; // GGX samples per texel
};

// Level 0 (roughness 0) is the filtered copy of the input.
std::vector<EnvironmentMap> prefilter_ggx(const EnvironmentMap& in, const PrefilterOptions& opt,
                                          Progress* progress = nullptr);
// Rows of the mip chain prefilter_ggx computes (for a progress bar's total).
int prefilter_rows(const PrefilterOptions& opt);

// The BRDF integration table: x = N·V in (0, 1], y = roughness in [0, 1] (texel centres), red = A (scale
// of F0), green = B (bias), blue = 0.
Image brdf_lut(int size, int samples);

} // namespace illum

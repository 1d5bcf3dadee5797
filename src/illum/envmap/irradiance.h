// The exact irradiance environment map by brute-force convolution with the clamped cosine:
// E(n) = Σ_texels L_i max(0, n · ω_i) Ω_i over a (downsampled) latitude-longitude copy of the input.
// O(N_out x N_in): the input is first resampled to at most `input_height` rows (64 x 128 texels by
// default: irradiance is smooth, and the filtered copy keeps the map's energy).
#pragma once

#include "illum/envmap/environment_map.h"

namespace illum {

class Progress;

EnvironmentMap brute_force_irradiance(const EnvironmentMap& in, EnvLayout out_layout, int out_height,
                                      int input_height = 64, Progress* progress = nullptr);
// E at one normal (for tests): the same sum over a prepared map.
Color3 brute_force_irradiance_at(const EnvironmentMap& latlong, Vector3f n);

} // namespace illum

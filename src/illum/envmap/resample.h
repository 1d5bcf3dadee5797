// Resampling an environment map into another layout (or size) with filtering: each output texel is the
// solid-angle-weighted mean of the input radiance over the texel, L_out = ∫ L dω / ∫ dω, estimated by
// k x k sub-samples weighted by the output layout's Jacobian, with k chosen from the ratio of the output
// texel's solid angle to the input's mean texel solid angle (box filter by area; the input is read
// bilinearly). Texels outside an output layout's domain (a probe's corners) are black.
#pragma once

#include "illum/envmap/environment_map.h"

namespace illum {

class Progress;

// height: the output's height in texels (its width follows the layout's aspect); 0 picks a height with
// about as many texels over the sphere as the input has. progress: optional, advanced by one per row.
EnvironmentMap resample(const EnvironmentMap& in, EnvLayout to, int height = 0, Progress* progress = nullptr);
// The output height resample() picks for height = 0.
int default_resample_height(const EnvironmentMap& in, EnvLayout to);

} // namespace illum

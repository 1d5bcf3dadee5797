// What the scene file's Integrator and Sampler directives ask of the render, read from their own
// parameters beside the integrators and samplers that use them.
#pragma once

#include "illum/param/entity.h"
#include "illum/render/scene.h"
#include "illum/util/diagnostics.h"

namespace illum {

// Integrator: pbrt-v4's "path", "volpath" (surfaces only until media land), "simplepath", illum's
// "direct" (pbrt-v3's "directlighting"), "albedo", "normal", "lightpath", "sppm" ("photonsperiteration"
// (-1: the pixel count), "radius" (1), "seed" (6502)); "maxdepth" (5), "regularize" (false; true is
// warned), "lightsampler" (uniform, power, bvh (the default) or exhaustive, as pbrt-v4's).
// The other pbrt-v4 integrators render with "path", warned. Sampler: every pbrt-v4 sampler but "sobol"
// as pbrt-v4 defines it (sampler.h), "sobol" is illum's padded Owen-scrambled Sobol; "pixelsamples" (16),
// "seed" (the CLI's --seed wins when given), "randomization" (zsobol, paddedsobol: "fastowen"; halton:
// "permutedigits"), stratified's "xsamples", "ysamples" (4, 4; spp is their product) and "jitter" (true).
RenderRequest create_render_request(const EntityDesc& integrator, const EntityDesc& sampler,
                                    Diagnostics& diag);

} // namespace illum

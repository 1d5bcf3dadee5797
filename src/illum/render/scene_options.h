// pbrt-v4's Option directives (BasicSceneBuilder::Option), read into what the scene asks of the render:
//  - "seed" (integer): the sample sequences' seed, as --seed gives it (the command line's --seed wins);
//  - "disablepixeljitter" (bool): every camera sample passes through its pixel's centre with weight 1
//    (the pixel sample is still drawn, so later dimensions are unchanged, as in pbrt-v4);
//  - "disablewavelengthjitter" (bool): spectral mode's hero wavelength is sampled at u = 1/2 (the
//    wavelengths' own sample is still drawn);
//  - "forcediffuse" (bool): every surface scatters as a Lambertian reflector of its BSDF's albedo
//    (render/force_diffuse.h);
//  - "rendercoordsys" ("camera", "cameraworld", "world"): the space pbrt-v4 renders in, which changes
//    only its floating-point rounding; illum renders in world space and checks the value;
//  - "disabletexturefiltering" (bool): no ray differentials, every footprint zero (textures read the
//    finest image level, checkerboards are not filtered), as pbrt-v4's ComputeDifferentials then does.
//  - "displacementedgescale" (number > 0): scales plymesh's "edgelength", the longest edge its displacement
//    refines to (geometry/displace_mesh.h).
// "msereferenceimage", "msereferenceout", "pixelstats" and "wavefront" are
// recognised and warned (each names what it would do and why illum has none of it). Any other name, or a
// value of the wrong kind, is an error at the option, as in pbrt-v4.
#pragma once

#include "illum/param/param_set.h"
#include "illum/render/scene.h"
#include "illum/util/diagnostics.h"

namespace illum {

void read_scene_options(const ParamSet& options, RenderRequest& request, Diagnostics& diag);

} // namespace illum

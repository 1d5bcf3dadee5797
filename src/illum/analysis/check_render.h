// The renders `illum verify` measures: a pbrt-v4 scene given as text through the renderer's own parser,
// builder, integrators and render loop, and the mean of its pixels with the standard error (the pixels
// are independent estimates of the same quantity: each has its own scrambled sample sequence).
#pragma once

#include <memory>
#include <string>

#include "illum/analysis/verify_check.h"
#include "illum/render/renderer.h"

namespace illum {

std::unique_ptr<Scene> scene_from_text(const std::string& pbrt);
RenderResult render_check(const Scene& scene, const std::string& integrator, int max_depth, int spp,
                          const VerifyOptions& options);
// One channel's pixel mean and its standard error.
Estimate pixel_estimate(const Image& image, int channel);
// The same for a render, with the non-finite samples it dropped.
Estimate pixel_estimate(const RenderResult& render, int channel);

// A camera, film and integrator looking at the origin of a white (ρ = 1) Lambertian plane z = 0 through a
// 4·10⁻⁵ wide orthographic window, so each pixel shows E(origin)/π for the light `world` adds (depth 1).
std::string irradiance_receiver(const std::string& world, int resolution = 16);

} // namespace illum

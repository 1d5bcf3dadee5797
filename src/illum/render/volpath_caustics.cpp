#include "illum/render/volpath_caustics.h"

namespace illum {

namespace {

// With a time budget, the share of it the light-tracing pass gets (it traces short paths: most particles end
// at their first, non-specular, vertex).
constexpr double kCausticTimeShare = 0.2;

} // namespace

VolPathCausticsIntegrator::VolPathCausticsIntegrator(const Scene& scene, int max_depth)
    : WholeImageIntegrator(scene), camera_paths_(scene, max_depth, /*caustics_by_light_tracing=*/true),
      caustics_(scene, max_depth, /*caustics_only=*/true) {}

RenderResult VolPathCausticsIntegrator::render_image(const RenderOptions& options) const {
    RenderOptions camera_options = options, light_options = options;
    if (options.time_budget > 0) {
        camera_options.time_budget = options.time_budget * (1 - kCausticTimeShare);
        light_options.time_budget = options.time_budget * kCausticTimeShare;
    }
    // A preview sees the camera paths' passes, then the sum.
    light_options.preview = nullptr;
    RenderResult r = render(scene_, camera_paths_, camera_options);
    RenderResult c = caustics_.render_image(light_options);
    c.image = crop(c.image, scene_.output_bounds()); // render() kept the film's pixel bounds of r
    for (std::size_t i = 0; i < r.image.pixel_count(); ++i) r.image.data()[i] += c.image.data()[i];
    if (options.preview) options.preview->frame(r.image, r.spp, options.time_budget > 0 ? 0 : r.spp, 1.0);
    r.seconds += c.seconds;
    r.rays += c.rays;
    r.samples += c.samples;
    r.nonfinite_samples += c.nonfinite_samples;
    return r;
}

} // namespace illum

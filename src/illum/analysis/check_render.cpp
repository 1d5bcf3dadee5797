#include "illum/analysis/check_render.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {

std::unique_ptr<Scene> scene_from_text(const std::string& pbrt) {
    return build_scene(parse_pbrt_string(pbrt, "<illum verify>", "."));
}

RenderResult render_check(const Scene& scene, const std::string& integrator, int max_depth, int spp,
                          const VerifyOptions& o) {
    auto in = make_integrator(integrator, scene, max_depth);
    RenderOptions ro;
    ro.spp = spp;
    ro.threads = o.threads;
    ro.seed = o.seed;
    ro.quiet = true;
    return render(scene, *in, ro);
}

Estimate pixel_estimate(const Image& img, int channel) {
    double sum = 0, sum2 = 0;
    std::size_t n = img.pixel_count();
    for (std::size_t i = 0; i < n; ++i) {
        double v = img.data()[i][channel];
        sum += v;
        sum2 += v * v;
    }
    if (n < 2) return {n ? sum : 0.0, 0.0};
    double mean = sum / double(n), var = std::max(0.0, (sum2 - double(n) * mean * mean) / double(n - 1));
    return {mean, std::sqrt(var / double(n))};
}

Estimate pixel_estimate(const RenderResult& r, int channel) {
    Estimate e = pixel_estimate(r.image, channel);
    e.dropped = r.nonfinite_samples;
    return e;
}

std::string irradiance_receiver(const std::string& world, int resolution) {
    return fmt::format(R"(
Integrator "path" "integer maxdepth" [1]
LookAt 0.5 0 0.05  0 0 0  0 0 1
Camera "orthographic" "float screenwindow" [-0.00002 0.00002 -0.00002 0.00002]
Film "rgb" "integer xresolution" [{0}] "integer yresolution" [{0}]
PixelFilter "box"
WorldBegin
Material "diffuse" "rgb reflectance" [1 1 1]
Shape "trianglemesh" "point3 P" [-10 -10 0 10 -10 0 10 10 0 -10 10 0] "integer indices" [0 1 2 0 2 3]
{1}
)",
                       resolution, world);
}

} // namespace illum

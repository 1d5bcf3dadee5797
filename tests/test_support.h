// Helpers shared by tests: render a pbrt-v4 scene given as text, and estimate a mean with its standard
// error from independent pixels.
#pragma once

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <functional>
#include <gtest/gtest.h>
#include <string>

#include "illum/analysis/check_render.h"
#include "illum/image/image.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum::test {

inline std::string shared_dir() { return ILLUM_SHARED_DIR; }
inline bool have_shared() {
    return std::filesystem::is_directory(std::filesystem::path(shared_dir()) / "scenes");
}

struct RenderSetup {
    std::string integrator = "path";
    int max_depth = -2; // -2: the scene's
    int spp = 16;
    int threads = 0;
    std::uint64_t seed = 0;
    std::string sampler = "sobol";
    bool spectral = false;
    bool adaptive = false; // adaptive sampling (render/adaptive_sampling.h) with its default settings
};

// An integrator test's setup: the independent sampler (samples independent of each other, as the tests'
// variance estimates assume) and, unless given, seed 7.
inline RenderSetup independent_setup(const std::string& integrator, int spp, bool spectral = false,
                                     int max_depth = -2, std::uint64_t seed = 7) {
    RenderSetup s;
    s.integrator = integrator;
    s.spp = spp;
    s.spectral = spectral;
    s.max_depth = max_depth;
    s.sampler = "independent";
    s.seed = seed;
    return s;
}

inline RenderResult render_pbrt(const std::string& text, const RenderSetup& setup = {}) {
    SceneDesc desc = parse_pbrt_string(text, "<test>", ".");
    auto scene = build_scene(desc);
    auto integrator = make_integrator(setup.integrator, *scene,
                                      setup.max_depth == -2 ? scene->request.max_depth : setup.max_depth);
    RenderOptions opt;
    opt.spp = setup.spp;
    opt.threads = setup.threads;
    opt.seed = setup.seed;
    opt.sampler = setup.sampler;
    opt.quiet = true;
    opt.spectral = setup.spectral;
    opt.adaptive.enabled = setup.adaptive;
    return render(*scene, *integrator, opt);
}

// ../shared/scenes/NAME/test.pbrt rendered with its own sampler and its own integrator (or `integrator`),
// the film resized to resolution² when resolution > 0; a non-finite sample or pixel fails the test.
// `adjust`, when given, changes the built scene first (its render request, for example).
inline Image render_shared_scene(const std::string& name, int spp, std::uint64_t seed, int resolution = 0,
                                 bool spectral = false, const std::string& integrator = "", int threads = 0,
                                 const std::function<void(Scene&)>& adjust = {}) {
    SceneDesc desc = parse_pbrt_file(shared_dir() + "/scenes/" + name + "/test.pbrt");
    if (resolution > 0) desc.set_film_resolution(resolution, resolution);
    auto scene = build_scene(desc);
    if (adjust) adjust(*scene);
    auto in = make_integrator(integrator.empty() ? scene->request.integrator : integrator, *scene,
                              scene->request.max_depth);
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.sampler = scene->request.sampler;
    opt.quiet = true;
    opt.spectral = spectral;
    opt.threads = threads;
    RenderResult r = render(*scene, *in, opt);
    EXPECT_EQ(r.nonfinite_samples, 0u) << name;
    EXPECT_FALSE(r.image.has_non_finite()) << name;
    return r.image;
}

// A disk emitter of radiance L and radius r at height h above the origin, facing down, with a black
// material (for an irradiance receiver).
inline std::string disk_light(double r, double h, double L) {
    return fmt::format(R"(
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{} {} {}]
  Translate 0 0 {}
  ReverseOrientation
  Shape "disk" "float radius" [{}]
AttributeEnd
)",
                       L, L, L, h, r);
}

// A closed furnace: the camera inside a sphere that emits Le and reflects with Lambertian albedo ρ (a
// one-sided emitter facing inwards), path traced to unbounded depth; every pixel sees Le / (1 - ρ).
inline std::string closed_furnace(double rho, double le, int resolution) {
    return fmt::format(R"(
Integrator "path" "integer maxdepth" [-1]
LookAt 0.1 0.2 0  1 0.3 0.2  0 0 1
Camera "perspective" "float fov" [60]
Film "rgb" "integer xresolution" [{res}] "integer yresolution" [{res}]
WorldBegin
Material "diffuse" "rgb reflectance" [{rho} {rho} {rho}]
AreaLightSource "diffuse" "rgb L" [{le} {le} {le}]
ReverseOrientation
Shape "sphere" "float radius" [1]
)",
                       fmt::arg("rho", rho), fmt::arg("le", le), fmt::arg("res", resolution));
}

// An irradiance receiver: a white (ρ = 1) Lambertian plane z = 0 seen in a tiny orthographic window around
// the origin from the side, so every pixel shows E(origin)/π for the light that `world` adds (depth 1).
inline std::string irradiance_receiver(const std::string& world, const std::string& integrator = "direct",
                                       int resolution = 16) {
    return fmt::format(R"(
Integrator "{}" "integer maxdepth" [1]
LookAt 0.5 0 0.05  0 0 0  0 0 1
Camera "orthographic" "float screenwindow" [-0.00002 0.00002 -0.00002 0.00002]
Film "rgb" "integer xresolution" [{}] "integer yresolution" [{}]
PixelFilter "box"
WorldBegin
Material "diffuse" "rgb reflectance" [1 1 1]
Shape "trianglemesh" "point3 P" [-10 -10 0 10 -10 0 10 10 0 -10 10 0] "integer indices" [0 1 2 0 2 3]
{}
)",
                       integrator, resolution, resolution, world);
}

// The irradiance receiver lit by a one-sided disk light (radius 1, radiance 1) at height 2, facing down,
// with `occluder` (black material set) between them.
inline std::string disk_light_through(const std::string& occluder) {
    return irradiance_receiver(fmt::format(R"(
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Translate 0 0 2
  ReverseOrientation
  Shape "disk" "float radius" [1]
AttributeEnd
Material "diffuse" "rgb reflectance" [0 0 0]
{}
)",
                                           occluder));
}

// A box (x -1..0.5, y -0.5..1, z 0..1.2) on a grey floor under a small area light, 32 x 32 pixels, volpath
// maxdepth 6 (bdpt_test.cpp and vcm_test.cpp): `box` opens the box's AttributeBegin and gives what is
// inside it (a medium behind an interface, a subsurface material).
inline std::string box_on_floor_scene(const std::string& box) {
    return R"(
LookAt 0 -4 2.5  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [6]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [20 20 20]
  Translate 0.3 0.2 2.5
  ReverseOrientation
  Shape "disk" "float radius" [0.3]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
)" + box + R"(  Shape "trianglemesh" "point3 P" [-1 -0.5 0  0.5 -0.5 0  0.5 1 0  -1 1 0  -1 -0.5 1.2  0.5 -0.5 1.2  0.5 1 1.2  -1 1 1.2]
    "integer indices" [0 1 5 0 5 4 1 2 6 1 6 5 2 3 7 2 7 6 3 0 4 3 4 7 4 5 6 4 6 7 0 2 1 0 3 2]
AttributeEnd
)";
}

// A box of homogeneous chromatic scattering medium (behind a material-less interface) for box_on_floor_scene.
inline const char* kMediumBox =
    R"(MakeNamedMedium "smoke" "string type" "homogeneous" "rgb sigma_a" [0.2 0.3 0.4] "rgb sigma_s" [1 2 3] "float g" [0.3]
AttributeBegin
  MediumInterface "smoke" ""
  Material "interface"
)";

// Mean of one channel over the pixels and its standard error, treating pixels as independent
// estimates (they are: each has its own scrambled sample sequence): analysis's pixel_estimate.
struct MeanEstimate {
    double mean = 0, standard_error = 0;
};
inline MeanEstimate pixel_mean(const Image& img, int channel) {
    Estimate e = pixel_estimate(img, channel);
    return {e.mean, e.standard_error};
}

// Two renders A and B of independent seeds against a reference, one channel: d = (A - ref)² - (A - B)²/2
// averages to the reference's own variance (zero for an exact one) when A and the reference differ only
// by noise; mean_sigma is the σ of the mean of (A + B)/2 (tests/scenes/scenes_test.cpp).
struct PixelCheck {
    double d_mean = 0, d_se = 0, mse_ref = 0, mse_noise = 0, mean_sigma = 0;
};
inline PixelCheck pixel_check(const Image& a, const Image& b, const Image& ref, int c) {
    double sum = 0, sum2 = 0, mse_ref = 0, mse_ab = 0;
    std::size_t n = a.pixel_count();
    for (std::size_t i = 0; i < n; ++i) {
        double ea = a.data()[i][c] - ref.data()[i][c], eab = a.data()[i][c] - b.data()[i][c];
        double d = ea * ea - 0.5 * eab * eab;
        sum += d;
        sum2 += d * d;
        mse_ref += ea * ea;
        mse_ab += 0.5 * eab * eab;
    }
    PixelCheck k;
    k.d_mean = sum / n;
    k.d_se = std::sqrt((sum2 / n - k.d_mean * k.d_mean) / (n - 1));
    k.mse_ref = mse_ref / n;
    k.mse_noise = mse_ab / n;
    k.mean_sigma = std::sqrt(k.mse_noise / (2.0 * n)); // σ of the mean of (A + B) / 2
    return k;
}

} // namespace illum::test

// Volumetric path tracing against closed forms (issue "Participating media", acceptance 1). Each scene
// makes every pixel estimate the same value; tolerances are 4.5 standard errors measured over the pixels
// at a fixed seed plus a float allowance (radiometry_test.cpp's convention).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "illum/render/volpath_integrator.h"
#include "test_support.h"

namespace illum {
namespace {

using test::pixel_mean;
using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5;

void expect_channels(const RenderResult& r, const double expected[3], const std::string& what,
                     double rel_float = 2e-4) {
    for (int c = 0; c < 3; ++c) {
        auto m = pixel_mean(r.image, c);
        std::printf("%-44s ch %d expected %.6g measured %.6g +- %.2g\n", what.c_str(), c, expected[c], m.mean,
                    m.standard_error);
        EXPECT_NEAR(m.mean, expected[c], kSigmas * m.standard_error + rel_float * expected[c])
            << what << " channel " << c;
    }
    EXPECT_EQ(r.nonfinite_samples, 0u) << what;
}

// A camera looking down -z through the slab -d < z < 0 of medium "slab" (two interface planes that
// fill the view), with `light` behind it.
std::string slab_scene(const std::string& medium, double d, const std::string& light) {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [20]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [-1]
WorldBegin
{}
{}
Material "interface"
AttributeBegin
  MediumInterface "slab" ""
  Shape "trianglemesh" "point3 P" [-50 -50 0  50 -50 0  50 50 0  -50 50 0] "integer indices" [0 1 2 0 2 3]
    "normal N" [0 0 1  0 0 1  0 0 1  0 0 1]
  Shape "trianglemesh" "point3 P" [-50 -50 {d}  50 -50 {d}  50 50 {d}  -50 50 {d}]
    "integer indices" [0 1 2 0 2 3] "normal N" [0 0 -1  0 0 -1  0 0 -1  0 0 -1]
AttributeEnd
)",
                       medium, light, fmt::arg("d", -d));
}

RenderSetup volpath(int spp, bool spectral = false) {
    return test::independent_setup("volpath", spp, spectral);
}

// σ_s = 0: a ray through depth d keeps exp(-σ_a d) of the light behind (per channel, chromatic σ_a).
TEST(VolPath, AbsorbingSlabTransmittance) {
    const double d = 0.8, sa[3] = {0.5, 1.5, 3.0}, env = 0.6;
    std::string scene =
        slab_scene(fmt::format(R"(MakeNamedMedium "slab" "string type" "homogeneous" "rgb sigma_a" [{} {} {}]
                       "rgb sigma_s" [0 0 0])",
                               sa[0], sa[1], sa[2]),
                   d, fmt::format(R"(LightSource "infinite" "rgb L" [{0} {0} {0}])", env));
    double expected[3];
    for (int c = 0; c < 3; ++c) expected[c] = env * std::exp(-sa[c] * d);
    expect_channels(render_pbrt(scene, volpath(64)), expected, "absorbing slab, RGB");
}

// σ_s = 0 with emission Le against black: L = Le (1 - exp(-σ_a d)) (pbrt-v4's source term σ_a Le).
TEST(VolPath, EmittingAbsorbingSlab) {
    for (bool spectral : {false, true}) {
        const double d = 0.7, sa = 1.3, le[3] = {0.9, 0.5, 0.2};
        std::string scene = slab_scene(
            fmt::format(R"(MakeNamedMedium "slab" "string type" "homogeneous" "rgb sigma_a" [{0} {0} {0}]
                           "rgb sigma_s" [0 0 0] "rgb Le" [{1} {2} {3}])",
                        sa, le[0], le[1], le[2]),
            d, "");
        double expected[3];
        for (int c = 0; c < 3; ++c) expected[c] = le[c] * (1 - std::exp(-sa * d));
        // Spectral mode goes through the uplift and back (within ~1e-3 of the RGB).
        expect_channels(render_pbrt(scene, volpath(64, spectral)), expected,
                        spectral ? "emitting slab, spectral" : "emitting slab, RGB", spectral ? 4e-3 : 2e-4);
    }
}

// The white furnace: a sphere of non-absorbing medium (chromatic σ_s, forward scattering) in a uniform
// environment returns the environment's radiance, whatever the number of bounces.
TEST(VolPath, WhiteFurnaceSphere) {
    for (bool spectral : {false, true}) {
        std::string scene = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [18]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [-1]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0 0 0] "rgb sigma_s" [1 3 8] "float g" [0.5]
AttributeBegin
  MediumInterface "fog" ""
  Material "interface"
  Shape "sphere" "float radius" [1]
AttributeEnd
)";
        const double expected[3] = {0.5, 0.5, 0.5};
        expect_channels(render_pbrt(scene, volpath(32, spectral)), expected,
                        spectral ? "white furnace, spectral" : "white furnace, RGB", spectral ? 4e-3 : 2e-4);
    }
}

// Same image at any thread count (the tracking's generator is seeded from the sample, not the thread).
TEST(VolPath, DeterministicAcrossThreads) {
    std::string scene =
        slab_scene(R"(MakeNamedMedium "slab" "string type" "homogeneous" "rgb sigma_a" [0.2 0.2 0.2]
                                      "rgb sigma_s" [1 2 3] "float g" [-0.3])",
                   1.0, R"(LightSource "infinite" "rgb L" [1 1 1])");
    RenderSetup a = volpath(4), b = volpath(4);
    a.threads = 1;
    b.threads = 2;
    Image ia = render_pbrt(scene, a).image, ib = render_pbrt(scene, b).image;
    ASSERT_EQ(ia.pixel_count(), ib.pixel_count());
    for (std::size_t i = 0; i < ia.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(ia.data()[i][c], ib.data()[i][c]) << "pixel " << i;
}

// A sphere of subsurface material under a uniform environment and a distant spot of light.
std::string subsurface_sphere(const std::string& material, const std::string& extra = "") {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [20]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [-1]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
LightSource "spot" "point3 from" [2 3 4] "point3 to" [0 0 0] "float coneangle" [20] "rgb I" [30 30 30]
{}
AttributeBegin
  {}
  Shape "sphere" "float radius" [1]
AttributeEnd
)",
                       extra, material);
}

// Subsurface, acceptance 3: the material renders as its dielectric boundary around the homogeneous medium
// with the coefficients pbrt-v4 derives ("scale" times sigma_a, sigma_s), which is the exact answer; the
// two scenes are rendered with different seeds and agree within their combined standard error.
TEST(VolPath, SubsurfaceEqualsDielectricAroundMedium) {
    RenderSetup a = volpath(32), b = volpath(32);
    b.seed = 1234;
    RenderResult sss = render_pbrt(
        subsurface_sphere(R"(Material "subsurface" "rgb sigma_a" [0.2 0.4 0.8] "rgb sigma_s" [4 3 2]
                                       "float scale" [2] "float eta" [1.33])"),
        a);
    RenderResult exact = render_pbrt(
        subsurface_sphere(R"(MediumInterface "m" ""
                             Material "dielectric" "float eta" [1.33])",
                          R"(MakeNamedMedium "m" "string type" "homogeneous" "rgb sigma_a" [0.4 0.8 1.6]
                                             "rgb sigma_s" [8 6 4])"),
        b);
    for (int c = 0; c < 3; ++c) {
        auto x = pixel_mean(sss.image, c), y = pixel_mean(exact.image, c);
        double se = std::hypot(x.standard_error, y.standard_error);
        std::printf("subsurface vs exact, ch %d: %.5f vs %.5f +- %.2g\n", c, x.mean, y.mean, se);
        EXPECT_NEAR(x.mean, y.mean, kSigmas * se) << "channel " << c;
    }
}

// A non-absorbing subsurface sphere (albedo 1 inside a lossless dielectric) in a uniform environment returns
// the environment's radiance: Fresnel reflection, refraction and total internal reflection conserve energy.
TEST(VolPath, SubsurfaceWhiteFurnace) {
    std::string scene = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [18]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [-1]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
Material "subsurface" "rgb sigma_a" [0 0 0] "rgb sigma_s" [2 4 6] "float eta" [1.5] "float g" [0.3]
Shape "sphere" "float radius" [1]
)";
    const double expected[3] = {0.5, 0.5, 0.5};
    expect_channels(render_pbrt(scene, volpath(32)), expected, "subsurface white furnace");
}

// Single scattering of a point light in an infinite homogeneous medium, seen along one line (a tiny
// orthographic window): L = ∫ σ_s e^{-σ_t t} p(cos θ) I e^{-σ_t r} / r² dt, by quadrature. volpath samples it
// both by free flight and equiangularly towards the light (MIS); each alone is checked by the same total.
TEST(VolPath, PointLightSingleScatteringQuadrature) {
    const double sa = 0.1, ss = 0.4, g = 0.3, h = 0.3, zl = 2.0, intensity = 1.5;
    for (bool spectral : {false, true}) {
        std::string scene = fmt::format(R"(
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [{0} {0} {0}] "rgb sigma_s" [{1} {1} {1}]
  "float g" [{2}]
MediumInterface "fog" "fog"
Camera "orthographic" "float screenwindow" [-0.001 0.001 -0.001 0.001]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
Integrator "volpath" "integer maxdepth" [1]
WorldBegin
LightSource "point" "point3 from" [0 {3} {4}] "rgb I" [{5} {5} {5}]
)",
                                        sa, ss, g, h, zl, intensity);
        // The camera looks down +z (pbrt's default camera space); the light is at (0, h, zl).
        auto integrand = [&](double t) {
            double dz = zl - t, r2 = h * h + dz * dz, r = std::sqrt(r2), cos_theta = dz / r;
            double d = 1 + g * g - 2 * g * cos_theta;
            double phase = (1 - g * g) / (4 * M_PI * d * std::sqrt(d));
            return ss * std::exp(-(sa + ss) * t) * phase * intensity * std::exp(-(sa + ss) * r) / r2;
        };
        const int n = 400000;
        const double b = 40, dt = b / n;
        double sum = integrand(0) + integrand(b);
        for (int i = 1; i < n; ++i) sum += integrand(i * dt) * (i % 2 ? 4 : 2);
        double expected_value = sum * dt / 3;
        const double expected[3] = {expected_value, expected_value, expected_value};
        expect_channels(render_pbrt(scene, volpath(64, spectral)), expected,
                        spectral ? "point light single scattering, spectral"
                                 : "point light single scattering, RGB",
                        spectral ? 4e-3 : 2e-4);
    }
}

} // namespace
} // namespace illum

// (b) Focus: with the film placed for focus distance d, rays from the axial point at d converge on the film.
// At the paraxial focus the spot that remains is spherical aberration, whose transverse error grows as the
// cube of the aperture (third-order theory: Δy ∝ ρ³), so halving a small stop divides the RMS spot by 8; a
// film off focus by δ would add a blur ∝ δ ρ, linear in the stop, and break that ratio. The spots are
// compared with the diffraction-free expectation (zero for a perfect focus) and the Airy radius
// 1.22 λ N. Then a rendered point light peaks at the pixel paraxial magnification predicts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fmt/format.h>

#include "illum/camera/paraxial.h"
#include "lens_support.h"
#include "test_support.h"

namespace illum {
namespace {

using test::axial_spot;
using test::Spot;

TEST(RealisticFocus, AxialSpotIsSphericalAberrationOnly) {
    ILLUM_REQUIRE_DGAUSS();
    LensPrescription lens = test::dgauss();
    const double lambda = kLambdaD;
    for (double d : {10.0, 1.0, 0.5}) {
        RealisticCamera wide = test::make_camera(lens, 17.1, d, 36, 24, 43.27, 256);
        Spot full = axial_spot(wide.lens(), d, lambda);
        double f = wide.cardinal_points().efl();
        double big_mm = 4, small_mm = 2;
        Spot big = axial_spot(test::make_camera(lens, big_mm, d, 36, 24, 43.27, 256).lens(), d, lambda);
        Spot small = axial_spot(test::make_camera(lens, small_mm, d, 36, 24, 43.27, 256).lens(), d, lambda);
        // The Airy radius 1.22 λ N with N = f / stop diameter: the entrance pupil is larger than the stop
        // (~1.4x here), so this overestimates N and the radius, an upper bound.
        double airy_small = 1.22 * lambda * 1e-9 * f / (small_mm * 1e-3);
        std::printf(
            "d = %4.1f m: RMS spot at the film, f/2 (17.1 mm stop): %.2f um (best focus %.2f um at "
            "%+.1f um); 4 mm stop %.4f um; 2 mm stop %.5f um (ratio %.2f; Airy radius at 2 mm <= %.1f "
            "um); centroid %.1e m\n",
            d, full.rms * 1e6, full.best_rms * 1e6, full.best_z * 1e6, big.rms * 1e6, small.rms * 1e6,
            big.rms / small.rms, airy_small * 1e6, std::hypot(full.cx, full.cy));
        EXPECT_GT(small.rays, 100);
        // Centred on the axis (symmetric grid): to rounding.
        EXPECT_LT(std::hypot(full.cx, full.cy), 1e-9);
        // Third order: 8 for halving the stop; fifth-order aberration shifts it by ~(D / D_full)², a few
        // per cent (measured 7.6 to 7.8), hence 10%. A film 1 um off focus would add a defocus blur of
        // ~0.03 um RMS (1 um times the ray slope, ~1/50) to the 2 mm stop's ~0.08 um spot and pull the
        // ratio well outside.
        EXPECT_NEAR(big.rms / small.rms, 8.0, 0.8) << d;
        // Geometric spots far below the diffraction limit at the small stops: the film is in focus.
        EXPECT_LT(small.rms, 0.01 * airy_small);
        // Wide open (f/2) the spot is the lens's residual spherical aberration, ~13 um RMS, whose best
        // focus lies some 10 to 50 um from the paraxial one: the thick-lens focus is paraxial, as pbrt-v4's.
        EXPECT_LT(full.best_rms, 20e-6);
        EXPECT_LT(full.best_rms, full.rms);
    }
}

// A tiny emitting sphere 2 m away, off the axis where paraxial magnification puts its image at the centre
// of pixel (44, 14): the rendered image peaks there.
TEST(RealisticFocus, RenderedPointLightPeaksAtThePredictedPixel) {
    ILLUM_REQUIRE_DGAUSS();
    LensPrescription lens = test::dgauss();
    const int w = 64, h = 48;
    const double diag = 4e-3, d = 2.0;
    const double fw = diag / std::sqrt(1 + double(h * h) / (w * w)), fh = fw * h / w; // 50 um pixels
    RealisticCamera cam = test::make_camera(lens, 6, d, w, h, diag * 1e3, 256);
    ParaxialLens p = paraxial_lens(lens, kLambdaD);
    double m = p.magnification(d - cam.lens().front_z()); // < 0: the image is inverted on the film
    // Raster (x, y) looks at the film point (-(x/w - 1/2) fw, (y/h - 1/2) fh): object = film / m.
    const double rx = 44.5, ry = 14.5;
    double xf = -(rx / w - 0.5) * fw, yf = (ry / h - 0.5) * fh;
    double X = xf / m, Y = yf / m;
    EXPECT_GT(X, 0); // right of and above the axis, as the upright image shows it
    EXPECT_GT(Y, 0);
    std::string scene = fmt::format(R"(
Film "rgb" "integer xresolution" [{}] "integer yresolution" [{}] "float diagonal" [{}]
Camera "realistic" "string lensfile" "{}" "float aperturediameter" [6] "float focusdistance" [{}]
Sampler "independent" "integer pixelsamples" [64]
Integrator "path" "integer maxdepth" [1]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Translate {} {} {}
  Shape "sphere" "float radius" [0.0005]
AttributeEnd
)",
                                    w, h, diag * 1e3, test::dgauss_path(), d, X, Y, d);
    test::RenderSetup setup;
    setup.spp = 64;
    setup.sampler = "independent";
    RenderResult r = test::render_pbrt(scene, setup);
    int bx = -1, by = -1;
    float best = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (r.image(x, y)[1] > best) best = r.image(x, y)[1], bx = x, by = y;
    std::printf("peak %.4g at pixel (%d, %d), predicted (%.1f, %.1f); magnification %.5f\n", best, bx, by, rx,
                ry, m);
    EXPECT_GT(best, 0);
    EXPECT_EQ(bx, 44);
    EXPECT_EQ(by, 14);
}

} // namespace
} // namespace illum

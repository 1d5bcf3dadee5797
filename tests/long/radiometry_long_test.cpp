// Long analytic radiometry (label "long", `make test-long`): the closed furnace and the on-axis disk
// irradiance of tests/integrators/radiometry_test.cpp at many more samples. The tolerance is the same
// 4.5 standard errors of the pixel mean, so it is ~10x tighter than in the short tests: the standard error
// shrinks as 1/sqrt(pixels × spp), and a bias that hides in the short tests' noise shows here.
#include <gtest/gtest.h>

#include <cstdio>
#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

using test::pixel_mean;
using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5; // ~7e-6 two-sided false-alarm rate per channel check

// Returns the tolerance used, so tests can also check that it is tighter than the short test's.
double expect_radiance(const RenderResult& r, double expected, const std::string& what, double rel_float) {
    auto g = pixel_mean(r.image, 1);
    std::printf("%-34s expected %.6g, measured %.6g +- %.2g (%+.4f%%)\n", what.c_str(), expected, g.mean,
                g.standard_error, 100 * (g.mean / expected - 1));
    double widest = 0;
    for (int c = 0; c < 3; ++c) {
        auto m = pixel_mean(r.image, c);
        double tol = kSigmas * m.standard_error + rel_float * expected;
        widest = std::max(widest, tol);
        EXPECT_NEAR(m.mean, expected, tol)
            << what << " channel " << c << " (standard error " << m.standard_error << ")";
    }
    EXPECT_EQ(r.nonfinite_samples, 0u);
    return widest;
}

// Inside a sphere that emits Le and reflects with Lambertian albedo ρ, radiance is Le / (1 - ρ) in every
// direction (unbounded depth, Russian roulette). Short test: 24² pixels × 32 spp; here 64² × 1024
// (~228x the samples, standard error ~15x smaller).
TEST(RadiometryLong, ClosedFurnaceManySamples) {
    for (double rho : {0.5, 0.8, 0.95}) {
        const double le = 0.7;
        std::string scene = test::closed_furnace(rho, le, 64);
        RenderSetup s;
        s.max_depth = -1;
        s.spp = 1024;
        double expected = le / (1 - rho);
        double tol =
            expect_radiance(render_pbrt(scene, s), expected, fmt::format("furnace rho={}", rho), 1e-4);
        // The check is meaningful: the tolerance is well under 1% of the answer.
        EXPECT_LT(tol, 0.01 * expected) << "rho " << rho;
    }
}

// E = π L r² / (r² + h²) on the axis of a uniform disk, seen as E/π by the white receiver. Short test:
// 16² pixels × 16 spp; here 64² × 256 (256x the samples, standard error 16x smaller).
TEST(RadiometryLong, DiskIrradianceOnAxisManySamples) {
    const double L = 2.0;
    for (auto [r, h] : {std::pair{1.0, 1.0}, std::pair{0.5, 2.0}, std::pair{2.0, 0.5}}) {
        double expected = L * r * r / (r * r + h * h);
        std::string world = test::disk_light(r, h, L);
        for (const char* integrator : {"direct", "path"}) {
            RenderSetup s;
            s.integrator = integrator;
            s.spp = 256;
            double tol = expect_radiance(render_pbrt(test::irradiance_receiver(world, integrator, 64), s),
                                         expected, fmt::format("{} r={} h={}", integrator, r, h), 2e-5);
            EXPECT_LT(tol, 0.002 * expected) << integrator << " r=" << r << " h=" << h;
        }
    }
}

} // namespace
} // namespace illum

// (a) The traced lens against first-order theory: effective focal length and back focal distance found
// by tracing near-axis rays through RealisticCamera's tracer match the ray-transfer-matrix values of the
// prescription (paraxial.h), at three wavelengths; the matrix method itself matches the thick-lens
// (lensmaker's) formula; and the film the camera chose images its focus plane by the Gaussian formula.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "illum/camera/paraxial.h"
#include "illum/camera/thick_lens.h"
#include "lens_support.h"

namespace illum {
namespace {

// Tolerances: the brief's 0.5%, and a tight bound because both sides are exact first-order optics in the
// limit: a ray at height h departs from it by (h/f)² (spherical aberration), here 1e-5 f, so ~1e-10, and
// double rounding over 11 surfaces is ~1e-14. 1e-7 relative leaves room and still catches any error in a
// curvature sign, an index or a thickness (each moves f by far more).
constexpr double kBriefTolerance = 5e-3, kTight = 1e-7;

struct Traced {
    double efl, bfd;
};

// A ray parallel to the axis at height h from the scene: after the lens it crosses the axis at F'
// (bfd = rear vertex - z(F')) and regains height h at P' (efl = z(P') - z(F')). Its own arithmetic, not
// trace_cardinal_points.
Traced trace_paraxial(const LensSystem& lens, double lambda, double h) {
    LensRay in{{0, h, lens.front_z() + 0.1}, {0, 0, -1}}, out;
    EXPECT_GT(lens.trace_from_scene(in, lambda, &out), 0);
    double z_focus = out.o.z - out.o.y / out.d.y * out.d.z;
    double z_principal = out.o.z + (h - out.o.y) / out.d.y * out.d.z;
    return {z_principal - z_focus, lens.film_distance() - z_focus};
}

TEST(Paraxial, MatrixMethodMatchesTheThickLensFormula) {
    // Biconvex singlet R1 = 60 mm, R2 = -40 mm, t = 8 mm, n = 1.6: 1/f = (n-1) [1/R1 - 1/R2 + (n-1) t /
    // (n R1 R2)], BFD = f (1 - (n-1) t / (n R1)) (Hecht, Optics, eqs. 6.2 and 6.3).
    LensPrescription lens = parse_lens_file("60 8 1.6 20\n-40 50 1 20\n", "singlet");
    double n = 1.6, r1 = 0.06, r2 = -0.04, t = 0.008;
    double f = 1 / ((n - 1) * (1 / r1 - 1 / r2 + (n - 1) * t / (n * r1 * r2)));
    double bfd = f * (1 - (n - 1) * t / (n * r1));
    ParaxialLens p = paraxial_lens(lens, kLambdaD);
    EXPECT_NEAR(p.efl(), f, 1e-12);
    EXPECT_NEAR(p.back_focal_distance(), bfd, 1e-12);
    // And the tracer on the same singlet.
    Traced tr = trace_paraxial(LensSystem::from_prescription(lens, 0), kLambdaD, 1e-6);
    EXPECT_NEAR(tr.efl, f, kTight * f);
    EXPECT_NEAR(tr.bfd, bfd, kTight * f);
}

TEST(Paraxial, TracedFocalLengthsMatchTheMatrixMethod) {
    ILLUM_REQUIRE_DGAUSS();
    LensPrescription lens = test::dgauss();
    LensSystem system = LensSystem::from_prescription(lens, 0);
    for (double lambda : {486.13, 587.56, 656.27}) {
        ParaxialLens p = paraxial_lens(lens, lambda);
        double f = p.efl();
        for (double h : {1e-5 * f, 1e-6 * f}) {
            Traced tr = trace_paraxial(system, lambda, h);
            std::printf("lambda %.2f nm, h %.1e m: EFL traced %.6f mm, matrix %.6f mm; BFD traced %.6f mm, "
                        "matrix %.6f mm\n",
                        lambda, h, tr.efl * 1e3, f * 1e3, tr.bfd * 1e3, p.back_focal_distance() * 1e3);
            EXPECT_NEAR(tr.efl, f, kBriefTolerance * f);
            EXPECT_NEAR(tr.bfd, p.back_focal_distance(), kBriefTolerance * p.back_focal_distance());
            EXPECT_NEAR(tr.efl, f, kTight * f);
            EXPECT_NEAR(tr.bfd, p.back_focal_distance(), kTight * f);
        }
        // The camera's own cardinal points (trace_cardinal_points) agree, on both sides of the lens.
        std::optional<CardinalPoints> cp = trace_cardinal_points(system, lambda, paraxial_height(system));
        ASSERT_TRUE(cp);
        EXPECT_NEAR(cp->efl(), f, kTight * f);
        EXPECT_NEAR(cp->focal_object - cp->principal_object, f, kTight * f); // F lies in front of P
        EXPECT_NEAR(cp->focal_object - system.front_z(), p.front_focal_distance(), kTight * f);
    }
    // The nominal 50 mm, and a finite-height ray does not focus at F' (the tracer is not paraxial).
    EXPECT_NEAR(paraxial_lens(lens, kLambdaD).efl(), 0.050, 0.001);
    Traced marginal = trace_paraxial(system, kLambdaD, 0.010);
    EXPECT_GT(std::abs(marginal.bfd - paraxial_lens(lens, kLambdaD).back_focal_distance()), 1e-5);
}

// The film the camera sets for focus distance d lies where the matrix method images the plane at d.
TEST(Paraxial, CameraFilmIsAtTheImageOfTheFocusPlane) {
    ILLUM_REQUIRE_DGAUSS();
    LensPrescription lens = test::dgauss();
    ParaxialLens p = paraxial_lens(lens, kLambdaD);
    for (double d : {100.0, 10.0, 1.0, 0.3}) {
        RealisticCamera cam = test::make_camera(lens, 8, d, 36, 24, 43.27, 256);
        double object = d - cam.lens().front_z(); // focus distance is measured from the film
        EXPECT_NEAR(cam.lens().film_distance(), p.image_distance(object), 1e-6 * p.efl()) << d;
    }
    EXPECT_THROW(test::make_camera(lens, 8, 0.15, 36, 24, 43.27, 256), Error); // inside 4 f
}

} // namespace
} // namespace illum

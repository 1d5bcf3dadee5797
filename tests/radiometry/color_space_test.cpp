// The named RGB colour spaces: names, the RGB <-> XYZ matrices from primaries and white (SMPTE RP 177),
// the illuminants' normalisation, and the sigmoid polynomial's evaluation.
#include "illum/radiometry/color_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "illum/radiometry/daylight.h"
#include "illum/radiometry/spectra.h"

namespace illum {
namespace {

const char* const kNames[] = {"srgb", "rec2020", "aces2065-1", "dci-p3"};

TEST(ColorSpace, NamesArePbrtV4s) {
    for (const char* name : kNames) {
        const RGBColorSpace* cs = RGBColorSpace::named(name);
        ASSERT_NE(cs, nullptr) << name;
        EXPECT_EQ(cs->name(), name);
        EXPECT_EQ(&RGBColorSpace::by_index(cs->index()), cs);
    }
    EXPECT_EQ(RGBColorSpace::named("srgb"), &RGBColorSpace::srgb());
    EXPECT_EQ(RGBColorSpace::named("sRGB"), nullptr);
    EXPECT_EQ(RGBColorSpace::named("aces"), nullptr);
    EXPECT_EQ(RGBColorSpace::named(""), nullptr);
}

// ∫ I ȳ dλ = 1 by the quadrature every conversion uses (exact up to rounding: it is how I is scaled).
TEST(ColorSpace, IlluminantIsNormalisedToLuminanceOne) {
    for (const char* name : kNames) {
        const RGBColorSpace& cs = *RGBColorSpace::named(name);
        double y = integrate_spectrum([&](double l) { return cs.illuminant(l) * cie_y(l); });
        EXPECT_NEAR(y, 1.0, 1e-12) << name;
        EXPECT_EQ(cs.white_xyz()[1], 1.0) << name;
    }
}

// RGB (1, 1, 1) is the white, and RGB -> XYZ -> RGB is the identity (double matrices to rounding, the float
// copies to float precision).
TEST(ColorSpace, WhiteAndInverse) {
    for (const char* name : kNames) {
        const RGBColorSpace& cs = *RGBColorSpace::named(name);
        double xyz[3];
        cs.xyz_from_rgb(Color3(1.0f), xyz);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(xyz[a], cs.white_xyz()[a], 1e-12) << name;
        Color3 white = cs.rgb_from_xyz(xyz[0], xyz[1], xyz[2]);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(white[a], 1.0f, 1e-6f) << name;

        const double *m = cs.rgb_from_xyz_matrix_f64(), *n = cs.xyz_from_rgb_matrix_f64();
        const float *mf = cs.rgb_from_xyz_matrix(), *nf = cs.xyz_from_rgb_matrix();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                double p = 0, pf = 0;
                for (int k = 0; k < 3; ++k)
                    p += m[3 * r + k] * n[3 * k + c], pf += double(mf[3 * r + k]) * nf[3 * k + c];
                EXPECT_NEAR(p, r == c ? 1.0 : 0.0, 1e-12) << name << " " << r << c;
                EXPECT_NEAR(pf, r == c ? 1.0 : 0.0, 1e-6) << name << " " << r << c;
                EXPECT_EQ(mf[3 * r + c], float(m[3 * r + c]));
            }
        // A few colours through both directions.
        for (Color3 rgb : {Color3(0.2f, 0.5f, 0.9f), Color3(1, 0, 0), Color3(0.01f, 0.7f, 0.3f)}) {
            cs.xyz_from_rgb(rgb, xyz);
            Color3 back = cs.rgb_from_xyz(xyz[0], xyz[1], xyz[2]);
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(back[a], rgb[a], 1e-6f) << name;
        }
    }
}

// Each primary's XYZ has the primary's chromaticity.
TEST(ColorSpace, PrimariesHaveTheirChromaticities) {
    for (const char* name : kNames) {
        const RGBColorSpace& cs = *RGBColorSpace::named(name);
        const Chromaticity p[3] = {cs.red(), cs.green(), cs.blue()};
        for (int c = 0; c < 3; ++c) {
            Color3 rgb(0.0f);
            rgb[c] = 1;
            double xyz[3];
            cs.xyz_from_rgb(rgb, xyz);
            double s = xyz[0] + xyz[1] + xyz[2];
            EXPECT_NEAR(xyz[0] / s, p[c].x, 1e-12) << name << " primary " << c;
            EXPECT_NEAR(xyz[1] / s, p[c].y, 1e-12) << name << " primary " << c;
        }
    }
}

// The white point is the illuminant's own chromaticity under the CMFs. The published values (D65 0.3127,
// 0.3290, CIE 15:2004; ACES "D60" 0.32168, 0.33767, SMPTE ST 2065-1) are rounded and come from the CIE's
// tabulated CMFs; 5e-4 covers both the rounding and an analytic CMF fit (measured: D65 0.31273, 0.32909
// with Wyman et al.'s fit; daylight at 6000 K 0.32162, 0.33777).
TEST(ColorSpace, WhitePoints) {
    auto xy = [](const RGBColorSpace& cs) {
        const double* w = cs.white_xyz();
        double s = w[0] + w[1] + w[2];
        return Chromaticity{w[0] / s, w[1] / s};
    };
    for (const char* name : {"srgb", "rec2020", "dci-p3"}) {
        Chromaticity w = xy(*RGBColorSpace::named(name));
        EXPECT_NEAR(w.x, 0.3127, 5e-4) << name;
        EXPECT_NEAR(w.y, 0.3290, 5e-4) << name;
    }
    Chromaticity aces = xy(*RGBColorSpace::named("aces2065-1"));
    EXPECT_NEAR(aces.x, 0.32168, 5e-4);
    EXPECT_NEAR(aces.y, 0.33767, 5e-4);
}

// The sRGB matrix agrees with IEC 61966-2-1's (computed from the rounded white 0.3127, 0.3290): the
// difference in the white (above) moves the entries by up to ~2e-3.
TEST(ColorSpace, SrgbMatrixMatchesTheStandard) {
    const double iec[9] = {3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108,
                           0.0415560, 0.0556434,  -0.2040259, 1.0572252};
    const double* m = RGBColorSpace::srgb().rgb_from_xyz_matrix_f64();
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(m[i], iec[i], 3e-3) << i;
}

// The provisional daylight at 6504 K is D65 (CIE 15 tabulates D65 from the same formula; measured max
// relative difference 4e-4 at the 10 nm nodes, from the CIE's rounding of M1, M2).
TEST(ColorSpace, DaylightAt6504KIsD65) {
    for (int l = 380; l <= 780; l += 10) EXPECT_NEAR(cie_daylight(l, 6504) / cie_d65(l), 1.0, 2e-3) << l;
    EXPECT_NEAR(cie_daylight(560, 6000), 100.0, 1e-9); // normalised to 100 at 560 nm
}

TEST(ColorSpace, IntegrateSpectrumIsTheTrapezoidRule) {
    EXPECT_NEAR(integrate_spectrum([](double) { return 1.0; }), 470.0, 1e-9);
    EXPECT_NEAR(integrate_spectrum([](double l) { return l; }), 0.5 * (830.0 * 830 - 360.0 * 360), 1e-6);
    EXPECT_NEAR(integrate_spectrum([](double) { return 1.0; }, 5), 470.0, 1e-9);
}

// S(x) = 1/2 + x / (2 √(1 + x²)): 1/2 at 0, odd about it, 0 and 1 in the limits (also for huge and
// infinite x, where the formula would give NaN), and max_value() the maximum over 360..830 nm.
TEST(SigmoidPolynomial, Evaluation) {
    EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(0), 0.5f);
    EXPECT_NEAR(RGBSigmoidPolynomial::sigmoid(1), 0.5f + 0.5f / std::sqrt(2.0f), 1e-7f);
    EXPECT_NEAR(RGBSigmoidPolynomial::sigmoid(-3) + RGBSigmoidPolynomial::sigmoid(3), 1.0f, 1e-7f);
    EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(INFINITY), 1.0f);
    EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(-INFINITY), 0.0f);
    EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(1e30f), 1.0f);
    EXPECT_EQ(RGBSigmoidPolynomial::sigmoid(-1e30f), 0.0f);
    EXPECT_EQ((RGBSigmoidPolynomial{0, 0, INFINITY}(500)), 1.0f);
    EXPECT_EQ((RGBSigmoidPolynomial{0, 0, -INFINITY}(500)), 0.0f);
    EXPECT_EQ((RGBSigmoidPolynomial{0, 0, INFINITY}.max_value()), 1.0f);

    // c0 λ² + c1 λ + c2 with λ in nm: a bump around 550 nm.
    RGBSigmoidPolynomial bump{-1e-3f, 1.1f, -300.0f};
    double x = -1e-3 * 550 * 550 + 1.1 * 550 - 300;
    EXPECT_NEAR(bump(550), 0.5 + x / (2 * std::sqrt(1 + x * x)), 1e-5);

    const RGBSigmoidPolynomial cases[] = {bump,
                                          {1e-3f, -1.1f, 300.0f},
                                          {0, 0.05f, -30},
                                          {0, -0.05f, 30},
                                          {2e-4f, -0.1f, 10},
                                          {-2e-4f, 0.3f, -100}};
    for (const RGBSigmoidPolynomial& p : cases) {
        // The maximum of the same polynomial in double (max_value() works in double; in float the
        // rounding of terms ~1e2 moves S by ~1e-6 between neighbouring λ).
        double brute = 0;
        for (double l = 360; l <= 830; l += 0.01) {
            double x = (double(p.c0) * l + p.c1) * l + p.c2;
            brute = std::max(brute, 0.5 + x / (2 * std::sqrt(1 + x * x)));
        }
        EXPECT_NEAR(p.max_value(), brute, 1e-6) << p.c0 << " " << p.c1 << " " << p.c2;
    }
}

} // namespace
} // namespace illum

// The CIE's tabulated colour-matching functions and illuminants (radiometry/cie_tables.h through
// spectra.h and named_spectra.h) against the figures the CIE publishes for them: the sums of the 1 nm
// colour-matching functions, sample values, and the chromaticities of D65, A and F1..F12. A mistyped
// table entry, a shifted row or a wrong interpolation moves these figures by more than the tolerances,
// which are the rounding of the published figures (half a unit in their last digit) plus the measured
// effect of summing at 1 nm over linearly interpolated 5 nm tables where the CIE summed at 5 nm.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "illum/radiometry/named_spectra.h"
#include "illum/radiometry/spectra.h"

using namespace illum;

namespace {

Chromaticity xy_of(const PiecewiseLinearSpectrum& s) { return chromaticity(spectrum_to_xyz(s)); }

// The multi-lobe piecewise-Gaussian fit of Wyman, Sloan and Shirley, "Simple Analytic Approximations to
// the CIE XYZ Color Matching Functions", JCGT 2(2), 2013 (the multi-lobe fit): an independent check of
// every entry of the table (illum used it before the table).
double lobe(double x, double mu, double s1, double s2) {
    double t = (x - mu) / (x < mu ? s1 : s2);
    return std::exp(-0.5 * t * t);
}
double wyman_x(double l) {
    return 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
           0.065 * lobe(l, 501.1, 20.4, 26.2);
}
double wyman_y(double l) { return 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1); }
double wyman_z(double l) { return 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8); }

} // namespace

// The sums of the 1 nm table from 360 to 830 nm (pbrt-v4's CIE_Y_integral is the ȳ sum, 106.856895 in
// single precision): 106.865 (x̄), 106.857 (ȳ), 106.892 (z̄) to three decimals, so within 5e-4. The ȳ sum is
// also kCieYIntegral, to double rounding.
TEST(CieData, ColourMatchingFunctionSums) {
    double x = 0, y = 0, z = 0;
    for (int l = 360; l <= 830; ++l) x += cie_x(l), y += cie_y(l), z += cie_z(l);
    EXPECT_NEAR(x, 106.865, 5e-4);
    EXPECT_NEAR(y, 106.857, 5e-4);
    EXPECT_NEAR(z, 106.892, 5e-4);
    EXPECT_NEAR(y, kCieYIntegral, 1e-10);
    // The 1931 observer was normalised so that the equal-energy spectrum E is white, x = y = 1/3: with the
    // 1 nm table the three sums agree to 3.4e-4 of their value.
    Chromaticity e = chromaticity({x, y, z});
    EXPECT_NEAR(e.x, 1.0 / 3, 1e-4);
    EXPECT_NEAR(e.y, 1.0 / 3, 1e-4);
}

// Sample values of the table (ISO/CIE 11664-1), its interpolation and its support.
TEST(CieData, ColourMatchingFunctionValues) {
    EXPECT_DOUBLE_EQ(cie_y(555), 1.0);
    EXPECT_DOUBLE_EQ(cie_x(600), 1.0622);
    EXPECT_DOUBLE_EQ(cie_y(600), 0.631);
    EXPECT_DOUBLE_EQ(cie_z(450), 1.77211);
    EXPECT_DOUBLE_EQ(cie_x(360), 0.0001299);
    EXPECT_DOUBLE_EQ(cie_y(830), 0.00000045181);
    EXPECT_DOUBLE_EQ(cie_y(555.25), 0.75 * cie_y(555) + 0.25 * cie_y(556));
    EXPECT_EQ(cie_x(359.9), 0.0);
    EXPECT_EQ(cie_z(830.1), 0.0);
    EXPECT_EQ(cie_y(std::nan("")), 0.0);
}

// Every entry against the analytic fit (measured: within 0.015 for x̄, 0.008 for ȳ, 0.024 for z̄; 0.03
// allowed), and the table's smoothness: its second differences reach 1.4e-3 (x̄), 1.0e-3 (ȳ), 6.8e-3 (z̄),
// so twice that catches a mistyped digit in any entry above about 0.01 and a shifted or swapped row.
TEST(CieData, ColourMatchingFunctionsAreSmoothAndNearTheAnalyticFit) {
    for (int l = 360; l <= 830; ++l) {
        SCOPED_TRACE(l);
        EXPECT_NEAR(cie_x(l), wyman_x(l), 0.03);
        EXPECT_NEAR(cie_y(l), wyman_y(l), 0.03);
        EXPECT_NEAR(cie_z(l), wyman_z(l), 0.03);
        if (l == 360 || l == 830) continue;
        auto d2 = [l](double (*f)(double)) { return std::abs(f(l - 1) - 2 * f(l) + f(l + 1)); };
        EXPECT_LT(d2(cie_x), 3e-3);
        EXPECT_LT(d2(cie_y), 2e-3);
        EXPECT_LT(d2(cie_z), 1.4e-2);
    }
}

// D65: the CIE's chromaticity (0.31272, 0.32903) of CIE 015:2004; the value at 560 nm and the support.
TEST(CieData, D65) {
    Chromaticity c = chromaticity(spectrum_to_xyz(cie_d65));
    EXPECT_NEAR(c.x, 0.31272, 1e-4);
    EXPECT_NEAR(c.y, 0.32903, 1e-4);
    EXPECT_DOUBLE_EQ(cie_d65(560), 100.0);
    EXPECT_DOUBLE_EQ(cie_d65(300), 0.0341);
    EXPECT_DOUBLE_EQ(cie_d65(830), 60.3125);
    EXPECT_DOUBLE_EQ(cie_d65(382), 0.6 * 49.9755 + 0.4 * 52.3118); // the CIE's 1 nm table is this lerp
    EXPECT_EQ(cie_d65(299), 0.0);
    EXPECT_EQ(cie_d65(831), 0.0);
}

// Illuminant A from its formula: the CIE's tabulated values at 300, 560 and 830 nm (6 significant
// digits) and its chromaticity (0.44757, 0.40745).
TEST(CieData, IlluminantA) {
    EXPECT_NEAR(cie_illuminant_a(300), 0.930483, 5e-7);
    EXPECT_NEAR(cie_illuminant_a(560), 100.0, 1e-12);
    EXPECT_NEAR(cie_illuminant_a(830), 261.602, 5e-4);
    Chromaticity c = xy_of(*named_spectrum("stdillum-A"));
    EXPECT_NEAR(c.x, 0.44757, 1e-4);
    EXPECT_NEAR(c.y, 0.40745, 1e-4);
}

// F1..F12 against the chromaticities CIE 015 publishes for them, within 2e-4 (the measured differences
// are below 1.5e-5). For F10 the tables of chromaticities usually quote y = 0.35986; the CIE's spectrum of
// F10 gives 0.35896 (in every transcription of the table we compared, pbrt-v4's included), so the quoted
// figure appears to transpose two digits and the test uses 0.35896.
TEST(CieData, FluorescentChromaticities) {
    const Chromaticity published[12] = {{0.31310, 0.33727}, {0.37208, 0.37529}, {0.40910, 0.39430},
                                        {0.44018, 0.40329}, {0.31379, 0.34531}, {0.37790, 0.38835},
                                        {0.31292, 0.32933}, {0.34588, 0.35875}, {0.37417, 0.37281},
                                        {0.34609, 0.35896}, {0.38052, 0.37713}, {0.43695, 0.40441}};
    for (int i = 0; i < 12; ++i) {
        std::string name = "stdillum-F" + std::to_string(i + 1);
        SCOPED_TRACE(name);
        auto s = named_spectrum(name);
        ASSERT_TRUE(s);
        Chromaticity c = xy_of(*s);
        EXPECT_NEAR(c.x, published[i].x, 2e-4);
        EXPECT_NEAR(c.y, published[i].y, 2e-4);
    }
}

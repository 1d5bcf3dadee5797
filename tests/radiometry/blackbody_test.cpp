// Planck's law (radiometry/spectra.h): its chromaticities against the closed-form approximation of the
// Planckian locus by Kim et al., and pbrt-v4's peak normalisation.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/radiometry/spectra.h"

using namespace illum;

namespace {

// The Planckian locus as cubic splines in 1/T and x: B. Kang, O. Moon, C. Hong, H. Lee, B. Cho and
// Y. Kim, "Design of advanced color temperature control system for HDTV applications", J. Korean Phys.
// Soc. 41(6), 865-871 (2002), eqs. for x_c(T) and y_c(x_c), 1667 K <= T <= 25000 K.
Chromaticity kim_planckian_locus(double t) {
    double t1 = 1e3 / t, t2 = t1 * t1, t3 = t2 * t1;
    double x = t <= 4000 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                         : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
    double x2 = x * x, x3 = x2 * x;
    double y = t <= 2222   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
               : t <= 4000 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                           : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    return {x, y};
}

} // namespace

// The spline approximates the locus to a few 1e-4 (measured here: within 5.4e-4, at 2500 K); 1e-3 still
// catches a wrong constant in Planck's law or a wrong colour-matching function.
TEST(Blackbody, ChromaticityFollowsThePlanckianLocus) {
    for (double t : {1667.0, 2000.0, 2500.0, 2856.0, 3500.0, 4000.0, 5000.0, 6500.0, 10000.0, 25000.0}) {
        SCOPED_TRACE(t);
        Chromaticity c = chromaticity(spectrum_to_xyz([t](double l) { return blackbody(l, t); }));
        Chromaticity k = kim_planckian_locus(t);
        EXPECT_NEAR(c.x, k.x, 1e-3);
        EXPECT_NEAR(c.y, k.y, 1e-3);
    }
}

// pbrt-v4's BlackbodySpectrum: Planck's law over its value at Wien's peak, so its maximum is 1 and lies at
// λ_max = 2.8977721e-3 m K / T.
TEST(Blackbody, NormalisedToItsPeak) {
    for (double t : {1000.0, 2856.0, 6500.0, 12000.0}) {
        SCOPED_TRACE(t);
        double peak = 2.8977721e6 / t; // nm
        EXPECT_NEAR(blackbody_normalized(peak, t), 1.0, 1e-12);
        EXPECT_LT(blackbody_normalized(peak * 0.99, t), 1.0);
        EXPECT_LT(blackbody_normalized(peak * 1.01, t), 1.0);
        EXPECT_NEAR(blackbody_normalized(550, t), blackbody(550, t) / blackbody(peak, t), 1e-9);
    }
    EXPECT_EQ(blackbody_normalized(550, 0), 0.0);
    EXPECT_EQ(blackbody(550, -1), 0.0);
}

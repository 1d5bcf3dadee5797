// Dispersion formulas and pbrt-v4's named glasses (radiometry/glass.h): the Sellmeier coefficients
// against the refractive index n_d and Abbe number ν_d the SCHOTT catalogue lists for each glass, and the
// dense sampling of the named spectra against the formula.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "illum/radiometry/glass.h"
#include "illum/radiometry/named_spectra.h"

using namespace illum;

namespace {

// Fraunhofer lines: d (helium, 587.5618 nm), F (hydrogen, 486.1327 nm), C (hydrogen, 656.2725 nm).
constexpr double kD = 587.5618, kF = 486.1327, kC = 656.2725;

} // namespace

TEST(Glass, BK7IndexAtTheDLine) {
    const SchottGlass* g = schott_glass("glass-BK7");
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->index(kD), 1.5168, 1e-4);
}

// n_d and ν_d = (n_d - 1) / (n_F - n_C) of the SCHOTT data sheets (5 and 2 decimals): a mistyped
// coefficient moves n_d by more than the catalogue's rounding (5e-6) plus the Sellmeier fit's residual
// (the catalogue quotes it below 1e-5), and ν_d, which depends on the dispersion alone, by more than 0.01.
TEST(Glass, CatalogueIndexAndAbbeNumber) {
    struct Case {
        const char* name;
        double nd, vd;
    };
    const Case cases[] = {{"glass-BK7", 1.51680, 64.17},   {"glass-BAF10", 1.67003, 47.11},
                          {"glass-FK51A", 1.48656, 84.47}, {"glass-LASF9", 1.85025, 32.17},
                          {"glass-F5", 1.67271, 32.25},    {"glass-F10", 1.72828, 28.53},
                          {"glass-F11", 1.78472, 25.68}};
    ASSERT_EQ(schott_glasses().size(), std::size(cases));
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const SchottGlass* g = schott_glass(c.name);
        ASSERT_TRUE(g);
        double nd = g->index(kD), vd = (nd - 1) / (g->index(kF) - g->index(kC));
        EXPECT_NEAR(nd, c.nd, 2e-5);
        EXPECT_NEAR(vd, c.vd, 0.011);
    }
    EXPECT_FALSE(schott_glass("glass-SF5"));
}

// The named spectra sample the formula every 1 nm from 360 nm (or the coefficients' first wavelength)
// to 830 nm; between samples linear interpolation stays within 3e-6 of the formula (the curvature of
// N-SF11 near 370 nm is the largest), and beyond the samples the spectrum is constant.
TEST(Glass, NamedSpectraSampleTheFormula) {
    for (const SchottGlass& g : schott_glasses()) {
        SCOPED_TRACE(std::string(g.pbrt_name));
        auto s = named_spectrum(g.pbrt_name);
        ASSERT_TRUE(s);
        double first = std::max(360.0, g.min_nm);
        EXPECT_DOUBLE_EQ(s->lambda.front(), std::ceil(first));
        EXPECT_DOUBLE_EQ(s->lambda.back(), 830.0);
        double worst = 0;
        for (double l = s->lambda.front(); l <= 830; l += 0.25)
            worst = std::max(worst, std::abs((*s)(l)-g.index(l)));
        EXPECT_LT(worst, 3e-6);
        EXPECT_DOUBLE_EQ((*s)(300), s->value.front());
        EXPECT_DOUBLE_EQ((*s)(900), s->value.back());
    }
}

TEST(Glass, Formulas) {
    // Cauchy: n = A + B / λ², λ in µm.
    EXPECT_DOUBLE_EQ(cauchy_index(500, 1.5, 0.004), 1.5 + 0.004 / 0.25);
    // Sellmeier with one term: n² = 1 + B λ² / (λ² - C).
    const double b[3] = {1.0, 0, 0}, c[3] = {0.01, 0, 0};
    EXPECT_NEAR(sellmeier_index(1000, b, c), std::sqrt(1 + 1.0 / 0.99), 1e-15);
}

// pbrt-v4's named metal spectra reduced to RGB (radiometry/metal_spectra.h, conductor_rgb.h): every
// name resolves to a plausible index, and the RGB Fresnel of the fitted index reproduces the RGB of the
// spectral Fresnel reflectance. ConductorRgb.Table prints the table of docs/verification.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "illum/bsdf/fresnel.h"
#include "illum/radiometry/conductor_rgb.h"
#include "illum/radiometry/spectra.h"

using namespace illum;

namespace {

const char* const kElements[] = {"Ag", "Al", "Au", "Cu", "CuZn", "MgO", "TiO2"};
const double kDegrees[] = {0, 30, 45, 60, 70, 80};

double cos_deg(double d) { return std::cos(d * 3.14159265358979323846 / 180); }

// Largest |F_rgb(θ; η, k) - RGB(F(θ; η(λ), k(λ)))| over kDegrees and the channels in `channels`.
double max_reflectance_error(const MeasuredIndex& m, const ConductorRgb& c, bool skip_out_of_gamut = false) {
    double worst = 0;
    Color3 f0 = reflectance_rgb(m, 1.0);
    for (double d : kDegrees) {
        Color3 truth = reflectance_rgb(m, cos_deg(d));
        Color3 rgb = fresnel_complex(float(cos_deg(d)), c.eta, c.k);
        for (int ch = 0; ch < 3; ++ch)
            if (!(skip_out_of_gamut && f0[ch] > 1))
                worst = std::max(worst, double(std::abs(rgb[ch] - truth[ch])));
    }
    return worst;
}

// The RGB indices published with Mitsuba 0.5 that illum used before it integrated the tables itself
// (CuZn: Querry's η, k at 650, 550 and 450 nm).
struct OldRgb {
    const char* element;
    Color3 eta, k;
};
const OldRgb kMitsuba[] = {
    {"Ag", {0.155265f, 0.116723f, 0.138342f}, {4.82835f, 3.12225f, 2.14696f}},
    {"Al", {1.65746f, 0.880369f, 0.521229f}, {9.22387f, 6.26952f, 4.837f}},
    {"Au", {0.143119f, 0.374957f, 1.44248f}, {3.98316f, 2.38572f, 1.60322f}},
    {"Cu", {0.200438f, 0.924033f, 1.10221f}, {3.91295f, 2.45285f, 2.14219f}},
    {"CuZn", {0.444f, 0.527f, 1.094f}, {3.695f, 2.765f, 1.829f}},
};

} // namespace

TEST(ConductorRgb, EveryNamedMetalResolvesToAPlausibleIndex) {
    for (const char* el : kElements) {
        SCOPED_TRACE(el);
        auto eta = named_spectrum_rgb(std::string("metal-") + el + "-eta");
        auto k = named_spectrum_rgb(std::string("metal-") + el + "-k");
        ASSERT_TRUE(eta && k);
        bool dielectric = std::string(el) == "MgO" || std::string(el) == "TiO2";
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT((*eta)[c], 0.1f);
            EXPECT_LT((*eta)[c], 4.0f);
            if (dielectric) {
                EXPECT_GE((*k)[c], 0.0f);
                EXPECT_LT((*k)[c], 0.02f);
            } else {
                EXPECT_GT((*k)[c], 1.0f);
                EXPECT_LT((*k)[c], 10.0f);
            }
        }
    }
    EXPECT_FALSE(named_spectrum_rgb("metal-Xx-eta"));
    EXPECT_FALSE(named_spectrum_rgb("metal-Au-n"));
    EXPECT_FALSE(named_spectrum_rgb("metal-Au"));
}

TEST(ConductorRgb, ConstantSpectraReduceToGrey) {
    PiecewiseLinearSpectrum two{{300, 900}, {2.5, 2.5}};
    Color3 c = unbounded_spectrum_to_rgb(two);
    EXPECT_NEAR(c.r, 2.5f, 1e-5f);
    EXPECT_NEAR(c.g, 2.5f, 1e-5f);
    EXPECT_NEAR(c.b, 2.5f, 1e-5f);
    // A material with a constant index: both reductions return it, and its reflectance is grey.
    MeasuredIndex m{"const", {{300, 900}, {0.5, 0.5}}, {{300, 900}, {3.0, 3.0}}};
    for (ConductorRgb r : {integrated_index_rgb(m), fitted_index_rgb(m)})
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(r.eta[ch], 0.5f, 2e-3f);
            EXPECT_NEAR(r.k[ch], 3.0f, 2e-3f);
        }
    Color3 f = reflectance_rgb(m, 0.5);
    double exact = fresnel_conductor_exact(0.5, 0.5, 3.0);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(f[ch], exact, 1e-5);
}

// The double-precision complex Fresnel used for the spectra and the renderer's float closed form
// (bsdf/fresnel.h) are different formulations of Born & Wolf's equations.
TEST(ConductorRgb, ExactFresnelFormulationsAgree) {
    for (double eta : {0.05, 0.2, 0.5, 1.0, 1.5, 3.0})
        for (double k : {0.0, 0.5, 2.0, 5.0, 9.0})
            for (double d = 0; d <= 89; d += 7) {
                double a = fresnel_conductor_exact(cos_deg(d), eta, k);
                double b = fresnel_complex(float(cos_deg(d)), {float(eta), float(k)});
                EXPECT_NEAR(a, b, 2e-5) << eta << " " << k << " " << d;
            }
}

// The fitted index (illum's reduction) against the RGB of the spectral reflectance, 0..80°. Measured
// worst case 0.0081 (Cu, red, 80°); gold's red channel is out of the sRGB gamut (1.02 at normal
// incidence, more than any Fresnel reflectance) and is off by up to 0.047 (checked separately).
TEST(ConductorRgb, FittedIndexReproducesSpectralReflectance) {
    for (const MeasuredIndex& m : measured_indices()) {
        SCOPED_TRACE(std::string(m.element));
        const ConductorRgb* c = named_conductor_rgb(m.element);
        ASSERT_TRUE(c);
        EXPECT_LT(max_reflectance_error(m, *c, true), 0.01);
        EXPECT_LT(max_reflectance_error(m, *c), 0.05);
        // Normal incidence is matched exactly where it can be.
        Color3 f0 = reflectance_rgb(m, 1.0),
               fit = conductor_f0(SampledSpectrum(c->eta), SampledSpectrum(c->k)).rgb();
        for (int ch = 0; ch < 3; ++ch)
            if (f0[ch] <= 1) {
                EXPECT_NEAR(fit[ch], f0[ch], 1e-4);
            }
        // The test can fail: swapping η and k is far off.
        EXPECT_GT(max_reflectance_error(m, {c->k, c->eta}), 0.2);
    }
}

// The literal reduction (η and k integrated separately) is worse: measured worst 0.047 (Au, red) and
// 0.017 for Cu and CuZn.
TEST(ConductorRgb, IntegratedIndexIsWithinFivePercent) {
    for (const MeasuredIndex& m : measured_indices()) {
        SCOPED_TRACE(std::string(m.element));
        ConductorRgb c = integrated_index_rgb(m);
        EXPECT_LT(max_reflectance_error(m, c), 0.05);
        EXPECT_GT(max_reflectance_error(m, {c.k, c.eta}), 0.2);
    }
}

// Published linear-sRGB normal-incidence reflectances (Real-Time Rendering 4th ed., Table 9.2, by
// N. Hoffman; also Unity's "Metal Reflectance" node): gold (1.000, 0.766, 0.336) with red clipped to 1,
// copper (0.955, 0.637, 0.538), silver (0.972, 0.960, 0.915), aluminium (0.913, 0.921, 0.925).
TEST(ConductorRgb, NormalIncidenceMatchesPublishedValues) {
    struct Pub {
        const char* element;
        Color3 f0;
    };
    const Pub pubs[] = {{"Au", {1.000f, 0.766f, 0.336f}},
                        {"Cu", {0.955f, 0.637f, 0.538f}},
                        {"Ag", {0.972f, 0.960f, 0.915f}},
                        {"Al", {0.913f, 0.921f, 0.925f}}};
    for (const Pub& p : pubs) {
        SCOPED_TRACE(p.element);
        Color3 f0 = clamp(reflectance_rgb(*measured_index(p.element), 1.0), 0, 1);
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(f0[ch], p.f0[ch], 0.02f);
    }
    const ConductorRgb* au = named_conductor_rgb("Au");
    Color3 f = conductor_f0(SampledSpectrum(au->eta), SampledSpectrum(au->k)).rgb();
    EXPECT_GT(f.r, 0.95f);
    EXPECT_GT(f.r, f.g);
    EXPECT_GT(f.g, f.b);
}

// The old hard-coded Mitsuba 0.5 RGB indices against the spectral reference: measured worst 0.053
// (Au, red, which those values under-reflect as the integrated reduction does), 0.027 (Cu), 0.021 (CuZn),
// 0.018 (Al), 0.009 (Ag).
TEST(ConductorRgb, OldMitsubaValuesAgreeWithinMeasuredBound) {
    for (const OldRgb& o : kMitsuba) {
        SCOPED_TRACE(o.element);
        EXPECT_LT(max_reflectance_error(*measured_index(o.element), {o.eta, o.k}), 0.06);
    }
}

// The worst reflectance error of illum's fit, 0..80° and all channels, that docs/verification.md and
// conductor_rgb.h state (measured: Ag, Al 0.0002; Cu 0.0081; CuZn 0.0033; MgO, TiO2 below 0.00005), with a
// margin of about 25% (at least 0.0001) so that a change of the fit or of the colour matching
// functions that moves the table fails here and gets the documentation updated. Gold's red channel is
// out of the sRGB gamut (F(0°) = 1.02, more than a Fresnel reflectance can reach), so the fit falls short
// there by 0.0470 (its in-gamut channels are within 0.002); that shortfall is bounded too. (With the
// analytic fit to the colour-matching functions used before the CIE's table it was 0.0449: the tabulated
// functions make gold's red 1.022 instead of 1.020.)
struct FitBound {
    const char* element;
    double all_channels, in_gamut;
};
const FitBound kFitBounds[] = {{"Ag", 0.0003, 0.0003},  {"Al", 0.0003, 0.0003},   {"Au", 0.048, 0.002},
                               {"Cu", 0.0085, 0.0085},  {"CuZn", 0.0035, 0.0035}, {"MgO", 0.0001, 0.0001},
                               {"TiO2", 0.0001, 0.0001}};

// Prints the table of docs/verification.md ("Named metal spectra"), and checks its last column against
// the bounds above:
//   ./build/tests/illum_test_radiometry --gtest_filter=ConductorRgb.Table
TEST(ConductorRgb, Table) {
    int checked = 0;
    for (const MeasuredIndex& m : measured_indices()) {
        SCOPED_TRACE(std::string(m.element));
        const ConductorRgb& f = *named_conductor_rgb(m.element);
        const FitBound* bound = nullptr;
        for (const FitBound& b : kFitBounds)
            if (m.element == b.element) bound = &b;
        ASSERT_TRUE(bound) << "no documented bound for this metal";
        EXPECT_LT(max_reflectance_error(m, f), bound->all_channels);
        EXPECT_LT(max_reflectance_error(m, f, true), bound->in_gamut);
        // The fit is the better reduction for every metal (the reason illum uses it).
        EXPECT_LE(max_reflectance_error(m, f), max_reflectance_error(m, integrated_index_rgb(m)) + 1e-5);
        ++checked;
    }
    EXPECT_EQ(checked, int(std::size(kFitBounds)));

    std::printf(
        "| material | RGB η (fit) | RGB k (fit) | F(0°) spectral | F(0°) fit Δ | F(0°) integrated Δ | F(60°) "
        "spectral | F(60°) fit Δ | F(80°) spectral | F(80°) fit Δ | max Δ fit / integrated / Mitsuba |\n");
    auto c3 = [](Color3 c) {
        char b[64];
        std::snprintf(b, sizeof b, "%.3f %.3f %.3f", c.r, c.g, c.b);
        return std::string(b);
    };
    auto d3 = [](Color3 c) {
        char b[64];
        std::snprintf(b, sizeof b, "%+.3f %+.3f %+.3f", c.r, c.g, c.b);
        return std::string(b);
    };
    for (const MeasuredIndex& m : measured_indices()) {
        const ConductorRgb& f = *named_conductor_rgb(m.element);
        ConductorRgb in = integrated_index_rgb(m);
        double mitsuba = -1;
        for (const OldRgb& o : kMitsuba)
            if (m.element == o.element) mitsuba = max_reflectance_error(m, {o.eta, o.k});
        Color3 t0 = reflectance_rgb(m, 1), t60 = reflectance_rgb(m, cos_deg(60)),
               t80 = reflectance_rgb(m, cos_deg(80));
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %.4f / %.4f / %s |\n",
                    std::string(m.element).c_str(), c3(f.eta).c_str(), c3(f.k).c_str(), c3(t0).c_str(),
                    d3(fresnel_complex(1.0f, f.eta, f.k) - t0).c_str(),
                    d3(fresnel_complex(1.0f, in.eta, in.k) - t0).c_str(), c3(t60).c_str(),
                    d3(fresnel_complex(float(cos_deg(60)), f.eta, f.k) - t60).c_str(), c3(t80).c_str(),
                    d3(fresnel_complex(float(cos_deg(80)), f.eta, f.k) - t80).c_str(),
                    max_reflectance_error(m, f), max_reflectance_error(m, in),
                    mitsuba < 0 ? "-" : std::to_string(mitsuba).substr(0, 6).c_str());
    }
    std::printf("\nintegrated (η, k each reduced like a reflectance):\n");
    for (const MeasuredIndex& m : measured_indices()) {
        ConductorRgb in = integrated_index_rgb(m);
        std::printf("| %s | %s | %s |\n", std::string(m.element).c_str(), c3(in.eta).c_str(),
                    c3(in.k).c_str());
    }
}

// pbrt-v4's named spectra (radiometry/named_spectra.h): every name pbrt-v4 defines (src/pbrt/util/
// spectrum.cpp, Spectra::Init) resolves to a full spectrum and, for the RGB mode, to an RGB value;
// illuminants have luminance 1 as in pbrt-v4.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "illum/radiometry/metal_spectra.h"
#include "illum/radiometry/named_spectra.h"
#include "illum/radiometry/spectra.h"

using namespace illum;

namespace {

// pbrt-v4's names, in its order, without its camera sensitivities.
const std::vector<std::string> kPbrtNames = {
    "glass-BK7",    "glass-BAF10",    "glass-FK51A",  "glass-LASF9",    "glass-F5",     "glass-F10",
    "glass-F11",    "metal-Ag-eta",   "metal-Ag-k",   "metal-Al-eta",   "metal-Al-k",   "metal-Au-eta",
    "metal-Au-k",   "metal-Cu-eta",   "metal-Cu-k",   "metal-CuZn-eta", "metal-CuZn-k", "metal-MgO-eta",
    "metal-MgO-k",  "metal-TiO2-eta", "metal-TiO2-k", "stdillum-A",     "stdillum-D50", "stdillum-D65",
    "stdillum-F1",  "stdillum-F2",    "stdillum-F3",  "stdillum-F4",    "stdillum-F5",  "stdillum-F6",
    "stdillum-F7",  "stdillum-F8",    "stdillum-F9",  "stdillum-F10",   "stdillum-F11", "stdillum-F12",
    "illum-acesD60"};

// pbrt-v4's camera sensitivities "<camera>_r", "_g", "_b": deliberately absent (named_spectra.h says why).
const char* const kPbrtCameras[] = {
    "canon_eos_100d",     "canon_eos_1dx_mkii", "canon_eos_200d",    "canon_eos_200d_mkii", "canon_eos_5d",
    "canon_eos_5d_mkii",  "canon_eos_5d_mkiii", "canon_eos_5d_mkiv", "canon_eos_5ds",       "canon_eos_m",
    "hasselblad_l1d_20c", "nikon_d810",         "nikon_d850",        "sony_ilce_6400",      "sony_ilce_7m3",
    "sony_ilce_7rm3",     "sony_ilce_9"};

bool is_illuminant(const std::string& n) { return n.starts_with("stdillum-") || n.starts_with("illum-"); }

} // namespace

TEST(NamedSpectra, EveryPbrtNameResolves) {
    std::vector<std::string> listed(named_spectrum_names().begin(), named_spectrum_names().end());
    EXPECT_EQ(listed, kPbrtNames);
    for (const std::string& n : kPbrtNames) {
        SCOPED_TRACE(n);
        auto s = named_spectrum(n);
        ASSERT_TRUE(s);
        ASSERT_GE(s->lambda.size(), 2u);
        EXPECT_TRUE(std::is_sorted(s->lambda.begin(), s->lambda.end()));
        EXPECT_LE(s->lambda.front(), 380);
        EXPECT_GE(s->lambda.back(), 760); // MgO's measurements end at 767.7 nm, the others at 780 nm or later
        EXPECT_EQ(is_illuminant_name(n), is_illuminant(n));
        auto rgb = named_spectrum_rgb(n);
        ASSERT_TRUE(rgb);
        EXPECT_TRUE(rgb->is_finite());
        EXPECT_FALSE(rgb->has_negative());
    }
    for (const char* camera : kPbrtCameras)
        for (const char* channel : {"_r", "_g", "_b"})
            EXPECT_FALSE(named_spectrum(std::string(camera) + channel));
    for (const char* unknown : {"", "glass-SF5", "metal-Au", "metal-Au-n", "metal-Xx-eta", "stdillum-F13",
                                "stdillum-B", "stdillum-D75", "illum-D60"}) {
        EXPECT_FALSE(named_spectrum(unknown)) << unknown;
        EXPECT_FALSE(named_spectrum_rgb(unknown)) << unknown;
        EXPECT_FALSE(is_illuminant_name(unknown)) << unknown;
    }
}

// pbrt-v4 scales its named illuminants to luminance 1; the RGB mode keeps that luminance and D65 is the
// sRGB white. (Rec. 709 luminance of linear sRGB is Y, up to the rounding of the sRGB matrix: 1e-4.)
TEST(NamedSpectra, IlluminantsHaveLuminanceOne) {
    for (const std::string& n : kPbrtNames) {
        if (!is_illuminant(n)) continue;
        SCOPED_TRACE(n);
        EXPECT_NEAR(spectrum_to_xyz(*named_spectrum(n)).y, 1.0, 1e-12);
        EXPECT_NEAR(named_spectrum_rgb(n)->luminance(), 1.0, 1e-4);
    }
    Color3 d65 = *named_spectrum_rgb("stdillum-D65");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(d65[c], 1.0f, 1e-6f);
    Color3 a = *named_spectrum_rgb("stdillum-A"), f7 = *named_spectrum_rgb("stdillum-F7");
    EXPECT_GT(a.r, 1.3f * a.b);            // warm
    EXPECT_NEAR(f7.r / f7.b, 1.0f, 0.05f); // F7 is a D65 simulator
}

// Metals are the measured tables; glasses their Sellmeier index (the RGB mode: the index at 550 nm).
TEST(NamedSpectra, MetalsAndGlasses) {
    const MeasuredIndex* au = measured_index("Au");
    ASSERT_TRUE(au);
    auto eta = named_spectrum("metal-Au-eta"), k = named_spectrum("metal-Au-k");
    ASSERT_TRUE(eta && k);
    EXPECT_EQ(eta->lambda, au->eta.lambda);
    EXPECT_EQ(eta->value, au->eta.value);
    EXPECT_EQ(k->value, au->k.value);
    auto bk7 = named_spectrum("glass-BK7");
    Color3 bk7_rgb = *named_spectrum_rgb("glass-BK7");
    EXPECT_NEAR(bk7_rgb.g, (*bk7)(550), 1e-6);
    EXPECT_EQ(bk7_rgb.r, bk7_rgb.b);
    EXPECT_GT((*bk7)(400), (*bk7)(700)); // normal dispersion
}

// The light factory against pbrt-v4's file format: every parameter pbrt-v4 reads for a light type is read
// (none is left "not used"), with pbrt-v4's defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "illum/light/light_factory.h"
#include "illum/light/spot_light.h"
#include "illum/radiometry/spectra.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/util/error.h"

namespace illum {
namespace {

struct Made {
    SceneDesc desc; // owns the parameters the light was made from
    std::unique_ptr<Light> light;
    std::vector<std::string> warnings;
    std::vector<std::string> unused; // parameter names nothing read
};

// The first light of a scene whose world block is `world`.
Made make(const std::string& world) {
    Made m;
    m.desc = parse_pbrt_string("WorldBegin\n" + world + "\n", "<light test>", ".");
    EXPECT_EQ(m.desc.lights.size(), 1u);
    Diagnostics diag;
    m.light = make_light(m.desc.lights.at(0), diag);
    m.warnings = diag.warnings();
    for (const Param* p : m.desc.lights.at(0).params.unused()) m.unused.push_back(p->name);
    return m;
}

float cos_deg(double deg) { return float(std::cos(deg * 3.14159265358979323846 / 180)); }

TEST(LightFactory, SpotReadsConeDeltaAngle) {
    Made m = make(R"(LightSource "spot" "float coneangle" 40 "float conedeltaangle" 10)");
    EXPECT_TRUE(m.unused.empty()) << m.unused.front();
    EXPECT_TRUE(m.warnings.empty());
    auto* spot = dynamic_cast<const SpotLight*>(m.light.get());
    ASSERT_TRUE(spot);
    EXPECT_NEAR(spot->cos_end(), cos_deg(40), 1e-6);
    EXPECT_NEAR(spot->cos_start(), cos_deg(30), 1e-6);
}

TEST(LightFactory, SpotDefaultsArePbrtV4s) {
    Made m = make(R"(LightSource "spot")");
    auto* spot = dynamic_cast<const SpotLight*>(m.light.get());
    ASSERT_TRUE(spot);
    EXPECT_NEAR(spot->cos_end(), cos_deg(30), 1e-6);   // coneangle 30
    EXPECT_NEAR(spot->cos_start(), cos_deg(25), 1e-6); // conedeltaangle 5
}

// pbrt-v4: I(θ) = I · smoothstep(cos θ, cos(coneangle), cos(coneangle - conedeltaangle)).
TEST(LightFactory, SpotFalloffIsPbrtV4Smoothstep) {
    Made m = make(R"(LightSource "spot" "float coneangle" 50 "float conedeltaangle" 20)");
    auto* spot = dynamic_cast<const SpotLight*>(m.light.get());
    ASSERT_TRUE(spot);
    const double lo = cos_deg(50), hi = cos_deg(30);
    for (double deg = 0; deg <= 60; deg += 2.5) {
        double c = cos_deg(deg);
        double t = std::clamp((c - lo) / (hi - lo), 0.0, 1.0);
        EXPECT_NEAR(spot->falloff(float(c)), t * t * (3 - 2 * t), 1e-5) << deg << " degrees";
    }
}

// Each light with every parameter pbrt-v4 reads for it: all are used and none warns.
TEST(LightFactory, EveryPbrtV4ParameterIsRead) {
    const char* lights[] = {
        R"(LightSource "point" "rgb I" [1 2 3] "float scale" 2 "float power" 10 "point3 from" [0 1 0])",
        R"(LightSource "spot" "rgb I" [1 2 3] "float scale" 2 "float power" 10 "point3 from" [0 1 0]
               "point3 to" [0 0 0] "float coneangle" 40 "float conedeltaangle" 10)",
        R"(LightSource "distant" "rgb L" [1 2 3] "float scale" 2 "float illuminance" 5
               "point3 from" [0 0 1] "point3 to" [0 0 0])",
        R"(LightSource "infinite" "rgb L" [1 2 3] "float scale" 2 "float illuminance" 5)",
    };
    for (const char* text : lights) {
        Made m = make(text);
        EXPECT_TRUE(m.light) << text;
        for (const auto& u : m.unused) ADD_FAILURE() << text << ": \"" << u << "\" is not used";
        for (const auto& w : m.warnings) ADD_FAILURE() << text << ": " << w;
    }
}

// "portal" makes pbrt-v4's portal light, without a warning; "L" with "filename" is an error, as in pbrt-v4,
// at the position of "L".
TEST(LightFactory, InfinitePortalAndLWithFilenameIsAnError) {
    Made m = make(R"(LightSource "infinite" "rgb L" [1 1 1]
                         "point3 portal" [0 0 0  1 0 0  1 1 0  0 1 0])");
    EXPECT_TRUE(m.unused.empty());
    EXPECT_TRUE(m.warnings.empty());
    EXPECT_TRUE(m.light);
    try {
        make(R"(LightSource "infinite" "string filename" "sky.exr" "rgb L" [1 1 1])");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(
            std::string(e.what()).find(":2:52: infinite light: \"L\" and \"filename\" cannot both be given"),
            std::string::npos)
            << e.what();
    }
}

// pbrt-v4 reads "I" and "L" as spectra: blackbody, named, sampled or from a file, each normalised to
// luminance 1 before `scale`; RGB keeps its own luminance.
TEST(LightFactory, EmissionMayBeASpectrum) {
    auto intensity = [](const std::string& param) {
        Made m = make("LightSource \"point\" " + param + " \"float scale\" 2");
        EXPECT_TRUE(m.unused.empty()) << param;
        EXPECT_TRUE(m.warnings.empty()) << param;
        return Color3(m.light->power().rgb() / float(4 * kPi)); // Φ = 4π I
    };
    auto expect_color = [](Color3 got, Color3 want, const std::string& what) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-4f * std::max(1.0f, want[c])) << what;
    };
    expect_color(intensity(R"("rgb I" [1 2 3])"), Color3(2, 4, 6), "rgb");
    expect_color(intensity(R"("blackbody I" [3000])"), blackbody_rgb(3000) * 2.0f, "blackbody");
    EXPECT_NEAR(intensity(R"("blackbody I" [3000])").luminance(), 2, 1e-3);
    EXPECT_GT(blackbody_rgb(3000).r, blackbody_rgb(3000).b); // warm
    expect_color(intensity(R"("spectrum I" "stdillum-D65")"), Color3(2.0f), "stdillum-D65");
    EXPECT_NEAR(intensity(R"("spectrum I" "stdillum-A")").luminance(), 2, 1e-3);
    Color3 flat = intensity(R"("spectrum I" [300 7 800 7])");
    EXPECT_NEAR(flat.luminance(), 2, 1e-3); // the amplitude 7 is normalised away
    std::string file = (std::filesystem::temp_directory_path() /
                        ("illum_light_spectrum_" + std::to_string(::getpid()) + ".spd"))
                           .string();
    std::ofstream(file) << "# flat\n300 7\n800 7\n";
    expect_color(intensity("\"spectrum I\" \"" + file + "\""), flat, "spectrum file");
    std::filesystem::remove(file);

    // Every light type that takes an emission spectrum.
    for (const char* text :
         {R"(LightSource "spot" "blackbody I" [5000])", R"(LightSource "distant" "blackbody L" [5000])",
          R"(LightSource "infinite" "spectrum L" "stdillum-A")"}) {
        Made m = make(text);
        EXPECT_TRUE(m.light) << text;
        EXPECT_TRUE(m.unused.empty()) << text;
        EXPECT_TRUE(m.warnings.empty()) << text;
    }
    try {
        make(R"(LightSource "point" "float I" [3])");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("<light test>:2:21: parameter \"I\" has type float"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace illum

// The light factory against pbrt-v4's file format: every parameter pbrt-v4 reads for a light type is read
// (none is left "not used"), with pbrt-v4's defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "illum/light/light_factory.h"
#include "illum/light/spot_light.h"
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
    LightFactoryContext ctx{[&](const SourceLocation&, const std::string& w) { m.warnings.push_back(w); }};
    m.light = make_light(m.desc.lights.at(0), ctx);
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

} // namespace
} // namespace illum

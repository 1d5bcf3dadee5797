// Perlin noise and the noise textures (texture/noise.h, noise_textures.h): the properties that define them
// (zero on the lattice, bounded, zero mean, smooth; the sums are their octaves), the textures' ranges and
// pbrt-v4's kinds. The renders against pbrt-v4's are in docs/verification.md ("Noise textures").
#include <gtest/gtest.h>

#include <cmath>

#include "illum/math/rng.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/texture/noise.h"
#include "illum/texture/noise_textures.h"

namespace illum {
namespace {

TEST(PerlinNoise, ZeroOnTheLatticeBoundedAndZeroMean) {
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y)
            for (int z = -3; z <= 3; ++z) EXPECT_EQ(perlin_noise(float(x), float(y), float(z)), 0.0f);
    PCG32 rng;
    double sum = 0, sum2 = 0, worst = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        float x = 100 * rng.uniform_float() - 50, y = 100 * rng.uniform_float() - 50,
              z = 100 * rng.uniform_float() - 50;
        double v = perlin_noise(x, y, z);
        sum += v;
        sum2 += v * v;
        worst = std::max(worst, std::abs(v));
    }
    double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_LT(std::abs(mean), 5 * sd / std::sqrt(n)); // zero mean within noise
    EXPECT_LT(worst, 1.05);                           // |gradient · offset| interpolated: about 1 at most
    EXPECT_GT(sd, 0.1);
}

// pbrt-v4's own values (5f7a606's Noise, FBm and Turbulence with zero differentials, printed by a program
// linked against it outside this repository): the same permutation, gradients and fade give the same noise
// (to float rounding: the fade is evaluated in Horner form here).
TEST(PerlinNoise, MatchesPbrtV4) {
    const float cases[][4] = {{0.300000012f, 0.699999988f, 0.100000001f, -0.0971815065f},
                              {1.5f, -2.25f, 3.75f, 0.0182971954f},
                              {-7.0999999f, 4.4000001f, 0.5f, -0.191523135f},
                              {10.0100002f, 20.0200005f, -30.0300007f, 0.0301516913f},
                              {0.5f, 0.5f, 0.5f, -0.125f}};
    for (const auto& c : cases)
        EXPECT_NEAR(perlin_noise(c[0], c[1], c[2]), c[3], 1e-6f) << c[0] << " " << c[1];
    EXPECT_NEAR(fbm({0.37f, -1.2f, 2.9f}, 0.5f, 8), -0.184886545f, 1e-6f);
    EXPECT_NEAR(turbulence({0.37f, -1.2f, 2.9f}, 0.5f, 8), 0.342964917f, 1e-6f);
}

TEST(PerlinNoise, ContinuousAcrossCells) {
    for (float y : {0.3f, 1.7f})
        for (int x = -2; x <= 2; ++x) {
            float below = perlin_noise(float(x) - 1e-4f, y, 0.4f),
                  above = perlin_noise(float(x) + 1e-4f, y, 0.4f);
            EXPECT_NEAR(below, above, 1e-3f);
        }
}

TEST(PerlinNoise, FbmAndTurbulenceAreTheirOctaves) {
    Point3f p{0.37f, -1.2f, 2.9f};
    EXPECT_FLOAT_EQ(fbm(p, 0.5f, 1), perlin_noise(p));
    float two = perlin_noise(p) + 0.6f * perlin_noise(scaled(p, 1.99f));
    EXPECT_NEAR(fbm(p, 0.6f, 2), two, 1e-6f);
    float t2 = std::abs(perlin_noise(p)) + 0.6f * std::abs(perlin_noise(scaled(p, 1.99f))) + 0.36f * 0.2f;
    EXPECT_NEAR(turbulence(p, 0.6f, 2), t2, 1e-6f);
    EXPECT_NEAR(turbulence(p, 0.5f, 0), 0.2f, 1e-7f);
}

TEST(PerlinNoise, SumsDropTheOctavesFinerThanTheFootprint) {
    // pbrt-v4's FBm and Turbulence: n = clamp(-1 - log2 max(|∂p/∂x|, |∂p/∂y|), 0, max) octaves resolve. A
    // footprint of 2^-(k+1) resolves exactly k; the octave k then has weight smoothstep(0.3, 0.7, 0) = 0.
    const Point3f p{0.37f, -1.2f, 2.9f};
    const float omega = 0.6f;
    const int max_octaves = 8;
    auto dropped_allowance = [&](int k) { // 0.2 Σ_{k ≤ i < max} ω^i, the octaves left out
        double sum = 0;
        for (int i = k; i < max_octaves; ++i) sum += 0.2 * std::pow(omega, i);
        return sum;
    };
    for (int k = 0; k <= max_octaves; ++k) {
        const Vector3f small(0, std::ldexp(1.0f, -(k + 1)) * 0.5f, 0),
            large(std::ldexp(1.0f, -(k + 1)), 0, 0);
        EXPECT_NEAR(fbm(p, small, large, omega, max_octaves), fbm(p, omega, k), 1e-6f) << k;
        EXPECT_NEAR(fbm(p, large, small, omega, max_octaves), fbm(p, omega, k), 1e-6f) << k;
        // With k resolved, the octave k contributes its 0.2 ω^k allowance twice (the partial octave's and
        // the first dropped one's, both at amplitude ω^k, as pbrt-v4 sums them).
        EXPECT_NEAR(turbulence(p, large, small, omega, max_octaves),
                    turbulence(p, omega, k) + dropped_allowance(k), 1e-6f)
            << k;
    }
    // Half an octave more: n = 3.5, the octave 3 at smoothstep weight 1/2.
    const Vector3f half(std::exp2(-4.5f), 0, 0);
    const float noise3 = perlin_noise(scaled(p, 1.99f * 1.99f * 1.99f));
    EXPECT_NEAR(fbm(p, half, {}, omega, max_octaves),
                fbm(p, omega, 3) + 0.5f * std::pow(omega, 3.0f) * noise3, 1e-6f);
    EXPECT_NEAR(turbulence(p, half, {}, omega, max_octaves),
                turbulence(p, omega, 3) - 0.2f * std::pow(omega, 3.0f) +
                    std::pow(omega, 3.0f) * (0.5f * 0.2f + 0.5f * std::abs(noise3)) + dropped_allowance(3),
                1e-6f);
    // A footprint wider than the coarsest octave's half period leaves none; a zero one keeps them all.
    const Vector3f wide(4, 0, 0);
    EXPECT_EQ(fbm(p, wide, wide, omega, max_octaves), 0.0f);
    EXPECT_NEAR(turbulence(p, wide, wide, omega, max_octaves), 0.2 + dropped_allowance(0), 1e-6f);
    EXPECT_EQ(fbm(p, {}, {}, omega, max_octaves), fbm(p, omega, max_octaves));
}

TEST(NoiseTextures, OctavesFollowTheFootprintInTextureSpace) {
    // A texture space scaled by 4 makes the footprint 4 times longer there: two octaves fewer.
    FbmTexture fbm_texture(TextureMapping3D(Transform::scale(4, 4, 4)), 8, 0.5f);
    TextureEvalContext c;
    c.p = {0.1f, 0.3f, 0.7f};
    c.dpdx = {std::exp2(-6.0f), 0, 0}; // 2^-4 in texture space: n = 3
    EXPECT_NEAR(fbm_texture.evaluate(c), fbm(Point3f(0.4f, 1.2f, 2.8f), 0.5f, 3), 1e-6f);
}

TEST(NoiseTextures, PolkaDotsCoverTheirShareOfThePlane) {
    // About half the cells hold a dot of radius 0.35 (area 0.385 of the cell): about 19% of the plane.
    PCG32 rng;
    int inside = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i)
        inside += inside_polka_dot({200 * rng.uniform_float(), 200 * rng.uniform_float()});
    double share = double(inside) / n;
    EXPECT_GT(share, 0.12);
    EXPECT_LT(share, 0.27);
}

TEST(NoiseTextures, MarbleStaysInItsPalette) {
    MarbleTexture marble(TextureMapping3D(Transform()), 8, 0.5f, 2.5f, 0.6f);
    PCG32 rng;
    for (int i = 0; i < 10000; ++i) {
        TextureEvalContext c;
        c.p = {4 * rng.uniform_float(), 4 * rng.uniform_float(), 4 * rng.uniform_float()};
        Color3 v = marble.evaluate(c);
        // The control points lie in [0.2, 0.6], times 1.5; a Bézier stays in their hull.
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(v[k], 0.3f - 1e-5f);
            EXPECT_LE(v[k], 0.9f + 1e-5f);
        }
    }
}

TEST(NoiseTextures, BuildAsPbrtV4DefinesTheirKinds) {
    auto build = [](const std::string& textures) {
        return build_scene(parse_pbrt_string("WorldBegin\n" + textures, "<test>", "."));
    };
    auto ok = build(R"(Texture "a" "float" "fbm" "integer octaves" 5 "float roughness" 0.4
Texture "b" "float" "wrinkled"
Texture "c" "float" "windy"
Texture "d" "spectrum" "marble" "float scale" 2 "float variation" 0.3
Texture "e" "spectrum" "dots" "float uscale" 4 "rgb inside" [1 0 0] "rgb outside" [0 0 1]
Texture "f" "float" "dots"
Material "diffuse" "texture reflectance" "d"
Shape "sphere"
)");
    EXPECT_TRUE(ok->warnings.empty()) << ok->warnings.front();
    // The marble's octaves depend on the footprint, so camera rays carry differentials.
    EXPECT_TRUE(ok->texture_filtering);
    EXPECT_THROW(build("Texture \"a\" \"spectrum\" \"fbm\"\n"), Error);
    EXPECT_THROW(build("Texture \"a\" \"float\" \"marble\"\n"), Error);
    EXPECT_THROW(build("Texture \"a\" \"float\" \"fbm\" \"integer octaves\" -1\n"), Error);
}

} // namespace
} // namespace illum

#include "illum/image/tonemap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace illum {
namespace {

TEST(Srgb, KnownValues) {
    EXPECT_EQ(srgb_encode(0.0f), 0.0f);
    EXPECT_EQ(srgb_encode(1.0f), 1.0f);
    // The knee: both pieces give 0.04045 at x = 0.0031308 (12.92 * 0.0031308 = 0.040449936).
    EXPECT_NEAR(srgb_encode(0.0031308f), 0.040449936f, 1e-7f);
    EXPECT_NEAR(1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 0.040449936, 1e-6);
    EXPECT_NEAR(srgb_encode(0.0031309f), 0.0404512f, 2e-6f);
    EXPECT_NEAR(srgb_encode(0.001f), 0.01292f, 1e-7f); // linear segment
    EXPECT_NEAR(srgb_encode(0.5f), 0.735356983f, 1e-6f);
    EXPECT_NEAR(srgb_encode(0.18f), 0.461356129f, 1e-6f);
    EXPECT_NEAR(srgb_decode(0.5f), 0.214041140f, 1e-6f);
    EXPECT_NEAR(srgb_decode(0.04045f), 0.0031308f, 1e-8f);
    EXPECT_EQ(srgb8_encode(1.0f), 255);
    EXPECT_EQ(srgb8_encode(0.5f), 188); // 255 * 0.73536 = 187.52
    EXPECT_EQ(srgb8_encode(0.0f), 0);
    // Out of range and NaN are clamped.
    EXPECT_EQ(srgb_encode(-1.0f), 0.0f);
    EXPECT_EQ(srgb_encode(5.0f), 1.0f);
    EXPECT_EQ(srgb_encode(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

TEST(Srgb, DecodeInvertsEncode) {
    for (int i = 0; i <= 1000; ++i) {
        const float x = float(i) / 1000.0f;
        EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 2e-6f) << x;
        EXPECT_NEAR(srgb_encode(srgb_decode(x)), x, 2e-6f) << x;
    }
    for (int c = 0; c < 256; ++c) EXPECT_EQ(srgb8_encode(srgb8_decode(static_cast<unsigned char>(c))), c);
}

TEST(ToneMap, ParsesNames) {
    EXPECT_EQ(tonemap_from_string("clamp"), ToneMap::Clamp);
    EXPECT_EQ(tonemap_from_string("Reinhard"), ToneMap::Reinhard);
    EXPECT_EQ(tonemap_from_string("ACES"), ToneMap::Aces);
    EXPECT_EQ(tonemap_from_string("filmic"), std::nullopt);
    EXPECT_EQ(tonemap_from_string(""), std::nullopt);
    for (ToneMap t : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces})
        EXPECT_EQ(tonemap_from_string(to_string(t)), t);
}

TEST(ToneMap, KnownValues) {
    EXPECT_EQ(tonemap(0.3f, ToneMap::Clamp), 0.3f);
    EXPECT_EQ(tonemap(2.0f, ToneMap::Clamp), 1.0f);
    EXPECT_FLOAT_EQ(tonemap(1.0f, ToneMap::Reinhard), 0.5f);
    EXPECT_FLOAT_EQ(tonemap(3.0f, ToneMap::Reinhard), 0.75f);
    // Narkowicz at 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14).
    EXPECT_NEAR(tonemap(1.0f, ToneMap::Aces), 2.54 / 3.16, 1e-6);
    EXPECT_NEAR(tonemap(0.1f, ToneMap::Aces), 0.1 * (0.251 + 0.03) / (0.1 * (0.243 + 0.59) + 0.14), 1e-6);
    // Exposure in stops scales by 2^stops before the curve.
    EXPECT_FLOAT_EQ(tonemap(Color3(0.25f), ToneMap::Clamp, 2.0f).r, 1.0f);
    EXPECT_FLOAT_EQ(tonemap(Color3(0.25f), ToneMap::Clamp, -1.0f).g, 0.125f);
    EXPECT_FLOAT_EQ(tonemap(Color3(0.5f), ToneMap::Reinhard, 1.0f).b, 0.5f);
}

TEST(ToneMap, MonotoneAndInUnitInterval) {
    for (ToneMap t : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        float previous = tonemap(0.0f, t);
        EXPECT_EQ(previous, 0.0f);
        for (int i = -600; i <= 600; ++i) {
            const float x = std::pow(10.0f, float(i) / 100.0f); // 1e-6 .. 1e6
            const float y = tonemap(x, t);
            EXPECT_GE(y, 0.0f) << to_string(t) << " " << x;
            EXPECT_LE(y, 1.0f) << to_string(t) << " " << x;
            EXPECT_GE(y, previous) << to_string(t) << " " << x;
            if (t == ToneMap::Reinhard && x < 1e3f) {
                EXPECT_GT(y, previous) << x;
            }
            previous = y;
        }
        EXPECT_EQ(tonemap(-2.0f, t), 0.0f);
        EXPECT_EQ(tonemap(std::numeric_limits<float>::quiet_NaN(), t), 0.0f);
        EXPECT_EQ(tonemap(std::numeric_limits<float>::infinity(), t), 1.0f);
    }
    // ACES approaches white for bright input (its asymptote a/c = 1.033 is clamped).
    EXPECT_EQ(tonemap(1e4f, ToneMap::Aces), 1.0f);
}

TEST(ToneMap, TonemappedImage) {
    Image img(2, 1);
    img(0, 0) = Color3(1.0f, 3.0f, -1.0f);
    img(1, 0) = Color3(0.0f);
    const Image out = tonemapped(img, ToneMap::Reinhard);
    EXPECT_EQ(out.width(), 2);
    EXPECT_FLOAT_EQ(out(0, 0).r, 0.5f);
    EXPECT_FLOAT_EQ(out(0, 0).g, 0.75f);
    EXPECT_EQ(out(0, 0).b, 0.0f);
    EXPECT_EQ(out(1, 0), Color3(0.0f));
}

} // namespace
} // namespace illum

// The measured media table (measured_media.h) spot-checked against the papers' values as pbrt-v4 lists
// them (src/pbrt/media.cpp: name, σ'_s or σ_s, σ_a [mm^-1]).
#include <gtest/gtest.h>

#include <set>

#include "illum/medium/measured_media.h"

namespace illum {
namespace {

void expect_color(Color3 got, Color3 want) {
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(got[i], want[i]) << "channel " << i;
}

TEST(MeasuredMedia, JensenValues) {
    auto apple = measured_medium("Apple");
    ASSERT_TRUE(apple);
    expect_color(apple->sigma_a, {0.0030f, 0.0034f, 0.046f});
    expect_color(apple->sigma_s, {2.29f, 2.39f, 1.97f});
    auto skin = measured_medium("Skin1");
    ASSERT_TRUE(skin);
    expect_color(skin->sigma_a, {0.032f, 0.17f, 0.48f});
    expect_color(skin->sigma_s, {0.74f, 0.88f, 1.01f});
    auto ketchup = measured_medium("Ketchup");
    ASSERT_TRUE(ketchup);
    expect_color(ketchup->sigma_a, {0.061f, 0.97f, 1.45f});
    expect_color(ketchup->sigma_s, {0.18f, 0.07f, 0.03f});
    auto spectralon = measured_medium("Spectralon");
    ASSERT_TRUE(spectralon);
    EXPECT_TRUE(spectralon->sigma_a.is_black());
    expect_color(spectralon->sigma_s, {11.6f, 20.4f, 14.9f});
}

TEST(MeasuredMedia, NarasimhanValues) {
    auto espresso = measured_medium("Espresso");
    ASSERT_TRUE(espresso);
    expect_color(espresso->sigma_a, {4.7984f, 6.5751f, 8.8493f});
    expect_color(espresso->sigma_s, {0.72378f, 0.84557f, 1.0247f});
    auto merlot = measured_medium("Merlot");
    ASSERT_TRUE(merlot);
    expect_color(merlot->sigma_a, {0.11632f, 0.25191f, 0.29434f});
    expect_color(merlot->sigma_s, {2.1129e-05f, 0.0f, 0.0f});
    auto hs = measured_medium("Head & Shoulders Shampoo");
    ASSERT_TRUE(hs);
    expect_color(hs->sigma_a, {0.084621f, 0.15688f, 0.20365f});
    expect_color(hs->sigma_s, {0.023805f, 0.028804f, 0.034306f});
    auto ocean = measured_medium("Pacific Ocean Surface Water");
    ASSERT_TRUE(ocean);
    expect_color(ocean->sigma_a, {0.031845f, 0.031324f, 0.030147f});
    expect_color(ocean->sigma_s, {0.0001764f, 0.00032095f, 0.00019617f});
}

TEST(MeasuredMedia, UnknownAndCaseSensitive) {
    EXPECT_FALSE(measured_medium("Unobtainium"));
    EXPECT_FALSE(measured_medium(""));
    EXPECT_FALSE(measured_medium("apple"));        // pbrt-v4 compares names exactly
    EXPECT_FALSE(measured_medium("Lowfat Milk ")); // no trimming either
}

TEST(MeasuredMedia, NamesListEveryEntryOnce) {
    const auto& names = measured_medium_names();
    EXPECT_EQ(names.size(), 47u); // 12 from Jensen et al. 2001, 35 from Narasimhan et al. 2006
    std::set<std::string> unique(names.begin(), names.end());
    EXPECT_EQ(unique.size(), names.size());
    for (const std::string& n : names) {
        auto m = measured_medium(n);
        ASSERT_TRUE(m) << n;
        EXPECT_TRUE(m->sigma_a.is_finite() && !m->sigma_a.has_negative()) << n;
        EXPECT_TRUE(m->sigma_s.is_finite() && !m->sigma_s.has_negative()) << n;
    }
    EXPECT_EQ(names.front(), "Apple");
    EXPECT_EQ(names.back(), "Pacific Ocean Surface Water");
}

} // namespace
} // namespace illum

#include "illum/image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "illum/util/error.h"

namespace illum {
namespace {

TEST(Image, ConstructsFilledAndRowMajor) {
    Image img(3, 2, Color3(0.5f, 1.0f, 2.0f));
    EXPECT_EQ(img.width(), 3);
    EXPECT_EQ(img.height(), 2);
    EXPECT_EQ(img.pixel_count(), 6u);
    EXPECT_FALSE(img.empty());
    EXPECT_EQ(img(2, 1), Color3(0.5f, 1.0f, 2.0f));
    img(2, 0) = Color3(7.0f);
    img.at(1, 1) = Color3(9.0f);
    EXPECT_EQ(img.data()[0 * 3 + 2], Color3(7.0f));
    EXPECT_EQ(img.data()[1 * 3 + 1], Color3(9.0f));
    EXPECT_EQ(Image().pixel_count(), 0u);
    EXPECT_TRUE(Image().empty());
}

TEST(Image, AtChecksBounds) {
    Image img(4, 3);
    EXPECT_NO_THROW(img.at(3, 2));
    EXPECT_THROW(img.at(4, 0), std::out_of_range);
    EXPECT_THROW(img.at(0, 3), std::out_of_range);
    EXPECT_THROW(img.at(-1, 0), std::out_of_range);
    const Image& c = img;
    EXPECT_THROW(c.at(0, -1), std::out_of_range);
}

TEST(Image, ResizeAndFill) {
    Image img(2, 2, Color3(1.0f));
    img.resize(5, 1, Color3(3.0f));
    EXPECT_EQ(img.width(), 5);
    EXPECT_EQ(img.height(), 1);
    for (int x = 0; x < 5; ++x) EXPECT_EQ(img(x, 0), Color3(3.0f));
    img.fill(Color3(0.25f));
    EXPECT_EQ(img(4, 0), Color3(0.25f));
    EXPECT_THROW(Image(-1, 2), Error);
    EXPECT_THROW(img.resize(2, -3), Error);
}

TEST(Image, ChannelMeanSumsInDouble) {
    // One huge pixel first, then many ones: a float running sum would stay at 1e8 (its ulp is 8) and
    // give 99900.1; the exact mean is (1e8 + 1000) / 1001 = 99900.999...
    Image img(1001, 1, Color3(1.0f));
    img(0, 0) = Color3(1e8f, 2e8f, 0.0f);
    const Color3 m = img.channel_mean();
    EXPECT_NEAR(m.r, (1e8 + 1000.0) / 1001.0, 0.02);
    EXPECT_NEAR(m.g, (2e8 + 1000.0) / 1001.0, 0.04);
    EXPECT_NEAR(m.b, 1000.0 / 1001.0, 1e-6);
    EXPECT_EQ(Image().channel_mean(), Color3(0.0f));
}

TEST(Image, DetectsNonFinite) {
    Image img(3, 3, Color3(1.0f));
    EXPECT_FALSE(img.has_non_finite());
    img(2, 2).g = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(img.has_non_finite());
    img(2, 2).g = 0;
    img(0, 1).b = -std::numeric_limits<float>::infinity();
    EXPECT_TRUE(img.has_non_finite());
}

} // namespace
} // namespace illum

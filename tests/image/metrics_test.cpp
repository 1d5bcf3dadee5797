#include "illum/image/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "illum/util/error.h"

namespace illum {
namespace {

// a - b = (0, 1, 2) and (-1, -1, -1); b = 1 everywhere.
struct Pair {
    Image a{2, 1}, b{2, 1, Color3(1.0f)};
    Pair() {
        a(0, 0) = {1, 2, 3};
        a(1, 0) = {0, 0, 0};
    }
};

TEST(Metrics, MseAndRmse) {
    Pair p;
    const ErrorStats m = mse(p.a, p.b);
    EXPECT_DOUBLE_EQ(m.channel[0], 0.5); // (0 + 1) / 2
    EXPECT_DOUBLE_EQ(m.channel[1], 1.0); // (1 + 1) / 2
    EXPECT_DOUBLE_EQ(m.channel[2], 2.5); // (4 + 1) / 2
    EXPECT_DOUBLE_EQ(m.overall, 4.0 / 3.0);
    const ErrorStats r = rmse(p.a, p.b);
    EXPECT_DOUBLE_EQ(r.channel[0], std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(r.channel[2], std::sqrt(2.5));
    EXPECT_DOUBLE_EQ(r.overall, std::sqrt(4.0 / 3.0));
    EXPECT_EQ(mse(p.b, p.b).overall, 0.0);
}

// A 10 x 10 image off by 0.1 everywhere but for one firefly of 1000 and a NaN pixel: the trimmed RMSE
// with 1.5% left out (floor(0.015 * 99) = 1 pixel) drops the firefly (the NaN pixel is not counted), leaving
// 0.1; with nothing left out it is the plain RMSE over the finite pixels.
TEST(Metrics, TrimmedRmseLeavesOutTheLargestErrors) {
    Image ref(10, 10, Color3(1.0f)), a(10, 10, Color3(1.1f));
    a(3, 4) = Color3(1000.0f);
    a(7, 7) = Color3(std::numeric_limits<float>::quiet_NaN());
    std::size_t trimmed = 0;
    const ErrorStats t = trimmed_rmse(a, ref, 0.015, &trimmed);
    EXPECT_EQ(trimmed, 1u);
    EXPECT_NEAR(t.overall, 0.1, 1e-6);
    EXPECT_NEAR(t.channel[1], 0.1, 1e-6);
    const ErrorStats all = trimmed_rmse(a, ref, 0.0, &trimmed);
    EXPECT_EQ(trimmed, 0u);
    EXPECT_NEAR(all.overall, std::sqrt((98 * 0.01 + 999.0 * 999.0) / 99.0), 1e-3);
    // compare_finite reports it beside the plain RMSE.
    const FiniteComparison d = compare_finite(a, ref, kRelativeEps, 0.015);
    ASSERT_TRUE(d.rmse_trimmed);
    EXPECT_NEAR(d.rmse_trimmed->overall, 0.1, 1e-6);
    EXPECT_GT(d.rmse->overall, 90.0);
    EXPECT_EQ(trimmed_rmse(a, ref, 0.005, &trimmed).overall, all.overall); // floor(0.495) = 0 pixels
    EXPECT_EQ(trimmed, 0u);
    EXPECT_THROW(trimmed_rmse(a, ref, 1.0), Error);
    EXPECT_THROW(trimmed_rmse(a, Image(5, 5), 0.01), Error);
}

TEST(Metrics, RelativeErrors) {
    Pair p;
    const ErrorStats r = rel_mse(p.a, p.b); // denominators 1^2 + 0.01
    EXPECT_DOUBLE_EQ(r.channel[0], 0.5 / 1.01);
    EXPECT_DOUBLE_EQ(r.channel[1], 1.0 / 1.01);
    EXPECT_DOUBLE_EQ(r.channel[2], 2.5 / 1.01);
    EXPECT_DOUBLE_EQ(r.overall, 4.0 / 3.0 / 1.01);
    const ErrorStats e = mean_relative_error(p.a, p.b); // |d| / (1 + 0.01)
    EXPECT_DOUBLE_EQ(e.channel[0], 0.5 / 1.01);
    EXPECT_DOUBLE_EQ(e.channel[1], 1.0 / 1.01);
    EXPECT_DOUBLE_EQ(e.channel[2], 1.5 / 1.01);
    EXPECT_DOUBLE_EQ(e.overall, 1.0 / 1.01);

    // The reference is the second argument, and eps matters for a black reference.
    Image black(1, 1, Color3(0.0f)), grey(1, 1, Color3(0.1f));
    EXPECT_NEAR(rel_mse(grey, black).overall, 0.01 / 0.01, 1e-6);
    EXPECT_NEAR(rel_mse(black, grey).overall, 0.01 / 0.02, 1e-6);
    EXPECT_NEAR(mean_relative_error(grey, black, 0.1).overall, 1.0, 1e-6);
    EXPECT_NEAR(mean_relative_error(black, grey, 0.1).overall, 0.5, 1e-6);
}

TEST(Metrics, RequireEqualSizes) {
    Image a(2, 2), b(2, 3);
    EXPECT_THROW(mse(a, b), Error);
    EXPECT_THROW(rmse(a, b), Error);
    EXPECT_THROW(rel_mse(a, b), Error);
    EXPECT_THROW(mean_relative_error(b, a), Error);
}

TEST(Metrics, MeansAndRelativeMeanDifference) {
    Pair p;
    const ErrorStats m = channel_means(p.a);
    EXPECT_DOUBLE_EQ(m.channel[0], 0.5);
    EXPECT_DOUBLE_EQ(m.channel[1], 1.0);
    EXPECT_DOUBLE_EQ(m.channel[2], 1.5);
    EXPECT_DOUBLE_EQ(m.overall, 1.0);
    const ErrorStats d = relative_mean_difference(p.a, p.b);
    EXPECT_DOUBLE_EQ(d.channel[0], -0.5);
    EXPECT_DOUBLE_EQ(d.channel[1], 0.0);
    EXPECT_DOUBLE_EQ(d.channel[2], 0.5);
    EXPECT_DOUBLE_EQ(d.overall, 0.0);
    // Sizes may differ: a 4x4 image of 2 against a 1x1 image of 1 is 100% brighter.
    EXPECT_DOUBLE_EQ(relative_mean_difference(Image(4, 4, Color3(2.0f)), Image(1, 1, Color3(1.0f))).overall,
                     1.0);
    // A black reference.
    const ErrorStats z = relative_mean_difference(Image(1, 1, Color3(0.0f, 1.0f, -1.0f)), Image(1, 1));
    EXPECT_EQ(z.channel[0], 0.0);
    EXPECT_TRUE(std::isinf(z.channel[1]) && z.channel[1] > 0);
    EXPECT_TRUE(std::isinf(z.channel[2]) && z.channel[2] < 0);
}

// compare_finite: the Pair with two pixels appended, one with a NaN in the image and one with an Inf in
// the reference. Every figure equals the plain metric of the finite pixels, and the counts say what went.
TEST(Metrics, CompareFiniteLeavesOutAndCountsInfAndNan) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    Pair p;
    Image a(4, 1), b(4, 1, Color3(1.0f));
    a(0, 0) = p.a(0, 0);
    a(1, 0) = p.a(1, 0);
    a(2, 0) = {5, nan, 5}; // one bad channel removes the whole pixel
    a(3, 0) = {7, 7, 7};
    b(3, 0) = {1, -inf, 1};
    EXPECT_EQ(count_nonfinite_pixels(a), 1u);
    EXPECT_EQ(count_nonfinite_pixels(b), 1u);
    EXPECT_TRUE(std::isnan(channel_means(a).channel[1])); // the plain metrics still report them

    const FiniteComparison d = compare_finite(a, b);
    EXPECT_EQ(d.nonfinite, 1u);
    EXPECT_EQ(d.reference_nonfinite, 1u);
    EXPECT_EQ(d.compared, 2u); // pixels 0 and 1
    Image a3(3, 1);            // a's finite pixels
    a3(0, 0) = a(0, 0);
    a3(1, 0) = a(1, 0);
    a3(2, 0) = a(3, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_DOUBLE_EQ(d.mean.channel[c], channel_means(a3).channel[c]);
        EXPECT_DOUBLE_EQ(d.reference_mean.channel[c], 1.0);
        EXPECT_DOUBLE_EQ(d.relative_mean_difference.channel[c], channel_means(a3).channel[c] - 1.0);
        ASSERT_TRUE(d.rmse && d.rel_mse && d.mean_relative_error);
        EXPECT_DOUBLE_EQ(d.rmse->channel[c], rmse(p.a, p.b).channel[c]);
        EXPECT_DOUBLE_EQ(d.rel_mse->channel[c], rel_mse(p.a, p.b).channel[c]);
        EXPECT_DOUBLE_EQ(d.mean_relative_error->channel[c], mean_relative_error(p.a, p.b).channel[c]);
    }
    EXPECT_DOUBLE_EQ(d.rmse->overall, rmse(p.a, p.b).overall);

    // Sizes differ: means only. All pixels non-finite: zeros, not NaN.
    const FiniteComparison e = compare_finite(Image(2, 2, Color3(inf)), Image(1, 1, Color3(1.0f)));
    EXPECT_EQ(e.nonfinite, 4u);
    EXPECT_FALSE(e.rmse);
    EXPECT_EQ(e.compared, 0u);
    EXPECT_EQ(e.mean.overall, 0.0);
}

TEST(Metrics, DownsampleAveragesBlocks) {
    Image img(4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) img(x, y) = Color3(float(x + 4 * y), 1.0f, float(x == 3 && y == 1) * 8);
    const Image d = downsample(img, 2);
    ASSERT_EQ(d.width(), 2);
    ASSERT_EQ(d.height(), 1);
    EXPECT_FLOAT_EQ(d(0, 0).r, (0 + 1 + 4 + 5) / 4.0f);
    EXPECT_FLOAT_EQ(d(1, 0).r, (2 + 3 + 6 + 7) / 4.0f);
    EXPECT_FLOAT_EQ(d(1, 0).g, 1.0f);
    EXPECT_FLOAT_EQ(d(0, 0).b, 0.0f);
    EXPECT_FLOAT_EQ(d(1, 0).b, 2.0f);
    EXPECT_EQ(downsample(img, 1), img);
    EXPECT_THROW(downsample(img, 3), Error);
    EXPECT_THROW(downsample(img, 0), Error);
}

} // namespace
} // namespace illum

// Environment-map light sampling: sample_li against pdf_li by a chi-square test over the map's texels
// (for each layout, with a rotation), a one-bright-texel map, and the layouts' Jacobians.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "illum/analysis/stats.h"
#include "illum/light/image_environment_light.h"
#include "illum/math/rng.h"
#include "math/stat_util.h"

namespace illum {
namespace {

// A test map in the given layout: smooth sky plus a bright sun-like spot (radius ~8.6°, 500x the sky).
EnvironmentMap sun_map(EnvLayout layout, int h) {
    int w = env_layout_aspect(layout) * h;
    Image img(w, h);
    Vector3f sun = normalize(Vector3f{0.4f, -0.5f, 0.7f});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            auto d = env_direction(layout, {(x + 0.5f) / w, (y + 0.5f) / h});
            if (!d) continue;
            float sky = 0.1f + std::max(0.0f, d->z);
            Color3 c(sky, sky, sky);
            if (dot(*d, sun) > std::cos(0.15f)) c += Color3(500.0f);
            img(x, y) = c;
        }
    return EnvironmentMap(std::move(img), layout);
}

// Layouts: direction(uv(d)) = d, and the Jacobian dω/dudv equals |∂ω/∂u × ∂ω/∂v| by finite differences;
// texel solid angles sum to 4π.
TEST(EnvLayouts, RoundTripAndJacobian) {
    for (EnvLayout l : {EnvLayout::LatLong, EnvLayout::Octahedral, EnvLayout::MirrorBall, EnvLayout::Angular,
                        EnvLayout::Cubemap}) {
        PCG32 rng(11);
        int checked = 0;
        for (int i = 0; i < 2000; ++i) {
            Point2f uv{0.02f + 0.96f * rng.uniform_float(), 0.02f + 0.96f * rng.uniform_float()};
            auto d = env_direction(l, uv);
            if (!d) continue;
            Point2f uv2 = env_uv(l, *d);
            auto d2 = env_direction(l, uv2);
            ASSERT_TRUE(d2);
            EXPECT_GT(dot(*d, *d2), 0.99999f) << to_string(l) << " at " << uv.x << "," << uv.y;
            const double e = 1e-3;
            auto du0 = env_direction(l, {uv.x - float(e), uv.y}),
                 du1 = env_direction(l, {uv.x + float(e), uv.y});
            auto dv0 = env_direction(l, {uv.x, uv.y - float(e)}),
                 dv1 = env_direction(l, {uv.x, uv.y + float(e)});
            if (!du0 || !du1 || !dv0 || !dv1) continue;
            // Near the probe disks' rims the maps are too steep for finite differences.
            float ra = std::hypot(2 * uv.x - 1, 2 * uv.y - 1);
            if ((l == EnvLayout::MirrorBall || l == EnvLayout::Angular) && ra > 0.9f) continue;
            // Skip the cube's face seams and the octahedron's folds, where the map is not differentiable.
            if (l == EnvLayout::Cubemap && std::abs(uv.x * 6 - std::round(uv.x * 6)) < 0.01f) continue;
            float p = 2 * uv.x - 1, q = 2 * uv.y - 1;
            if (l == EnvLayout::Octahedral && (std::abs(p) < 0.01f || std::abs(q) < 0.01f ||
                                               std::abs(std::abs(p) + std::abs(q) - 1) < 0.01f))
                continue;
            Vector3f a = (*du1 - *du0) / float(2 * e), b = (*dv1 - *dv0) / float(2 * e);
            float j = length(cross(a, b));
            EXPECT_NEAR(j, env_jacobian(l, uv), 3e-3 * env_jacobian(l, uv) + 1e-3) << to_string(l);
            ++checked;
        }
        EXPECT_GT(checked, 500) << to_string(l);
        EnvironmentMap m(Image(env_layout_aspect(l) * 64, 64), l);
        double total = 0;
        for (float s : m.solid_angles()) total += s;
        EXPECT_NEAR(total, 4 * kPiD, 2e-3) << to_string(l);
    }
}

// Chi-square of sample_li against pdf_li. The histogram bins are the map's texels, reached from the
// sampled world direction through the inverse rotation and the layout's uv; a bin's expected count is
// ∫ pdf_li dω = ∫ pdf_li(ω(u, v)) J(u, v) du dv over the texel (4x4 sub-samples: exact when pdf_li has
// the right Jacobian, since the product is then constant over the texel).
TEST(EnvSampling, ChiSquareAgainstPdf) {
    const std::vector<EnvLayout> layouts{EnvLayout::LatLong, EnvLayout::Octahedral, EnvLayout::Angular};
    const double alpha = sidak_significance(0.01, int(layouts.size()));
    for (EnvLayout layout : layouts) {
        EnvironmentMap map = sun_map(layout, 24);
        Transform rot = Transform::rotate(25, normalize(Vector3f{1, 2, 3}));
        ImageEnvironmentLight light(map, rot, 1.0f);
        Transform inv = rot.inverse();
        int w = map.width(), h = map.height();
        std::vector<double> observed(std::size_t(w) * h, 0.0), expected(observed.size(), 0.0);
        const int n = 400000;
        PCG32 rng(42);
        LightSampleContext ctx({0, 0, 0}, {}, {});
        int failed = 0, pdf_mismatches = 0;
        for (int i = 0; i < n; ++i) {
            auto s = light.sample_li(ctx, {rng.uniform_float(), rng.uniform_float()},
                                     SampledWavelengths::rgb_mode());
            if (!s) {
                ++failed;
                continue;
            }
            // The sample's own pdf equals pdf_li in its direction. (The angular map is singular at its rim,
            // θ = π, where float round-off grows; and a direction that maps back across a texel edge
            // meets the neighbour's density. Such samples must stay rare: a wrong Jacobian or density
            // fails for whole regions.)
            float p = light.pdf_li(ctx, s->wi, nullptr).value;
            if (std::abs(s->pdf.value - p) > (layout == EnvLayout::Angular ? 2e-2f : 2e-3f) * p)
                ++pdf_mismatches;
            Point2f uv = env_uv(layout, normalize(inv(s->wi)));
            int x = std::clamp(int(uv.x * w), 0, w - 1), y = std::clamp(int(uv.y * h), 0, h - 1);
            observed[std::size_t(y) * w + x] += 1;
        }
        EXPECT_LE(pdf_mismatches, n / 10000)
            << to_string(layout) << ": samples whose pdf differs from pdf_li";
        std::printf("%s: %d of %d samples' pdf differs from pdf_li beyond round-off\n", to_string(layout),
                    pdf_mismatches, n);
        const int k = 4;
        double total = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0;
                for (int j = 0; j < k; ++j)
                    for (int i = 0; i < k; ++i) {
                        Point2f uv{(x + (i + 0.5f) / k) / w, (y + (j + 0.5f) / k) / h};
                        auto d = env_direction(layout, uv);
                        if (!d) continue;
                        sum +=
                            light.pdf_li(ctx, normalize(rot(*d)), nullptr).value * env_jacobian(layout, uv);
                    }
                double mass = sum / (k * k) / (double(w) * h);
                expected[std::size_t(y) * w + x] = mass * n;
                total += mass;
            }
        EXPECT_NEAR(total, 1.0, 2e-3) << to_string(layout) << ": pdf_li integrates to " << total;
        if (layout != EnvLayout::Angular) {
            EXPECT_EQ(failed, 0);
        }
        // Angular: the rim texels are partly outside the disk; the midpoint rule is then approximate, so
        // pool them (the disk's interior is still tested texel by texel).
        if (layout == EnvLayout::Angular) {
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    float a = 2 * (x + 0.5f) / w - 1, b = 2 * (y + 0.5f) / h - 1;
                    if (std::sqrt(a * a + b * b) > 1 - 2.0f / w)
                        expected[std::size_t(y) * w + x] = observed[std::size_t(y) * w + x] = 0;
                }
        }
        auto r = test::chi2_test(observed, expected);
        EXPECT_GT(r.p_value, alpha) << to_string(layout) << ": chi2 = " << r.statistic << ", dof " << r.dof;
        EXPECT_GT(r.dof, 200);
    }
}

// One bright texel in a dim map takes almost every sample.
TEST(EnvSampling, OneBrightTexel) {
    for (EnvLayout layout : {EnvLayout::LatLong, EnvLayout::Octahedral}) {
        int h = 32, w = env_layout_aspect(layout) * h;
        Image img(w, h, Color3(1e-3f));
        int bx = w / 3, by = h / 4;
        img(bx, by) = Color3(1e5f);
        ImageEnvironmentLight light(EnvironmentMap(img, layout), Transform(), 1.0f);
        PCG32 rng(3);
        int hits = 0;
        const int n = 100000;
        for (int i = 0; i < n; ++i) {
            auto s = light.sample_li({}, {rng.uniform_float(), rng.uniform_float()},
                                     SampledWavelengths::rgb_mode());
            ASSERT_TRUE(s);
            Point2f uv = env_uv(layout, s->wi);
            hits += int(uv.x * w) == bx && int(uv.y * h) == by;
        }
        EXPECT_GT(hits, 0.99 * n) << to_string(layout);
    }
}

// A black map: no radiance, no power, uniform sampling by solid angle, no NaN.
TEST(EnvSampling, ZeroEnergyMap) {
    ImageEnvironmentLight light(EnvironmentMap(Image(16, 8), EnvLayout::LatLong), Transform(), 1.0f);
    light.preprocess(Bounds3f{{0, 0, 0}, {1, 1, 1}});
    EXPECT_EQ(light.power().rgb().luminance(), 0.0f);
    EXPECT_FALSE(light.sample_li({}, {0.3f, 0.7f}, SampledWavelengths::rgb_mode()));
    EXPECT_NEAR(light.pdf_li({}, normalize(Vector3f{1, 0, 0.1f}), nullptr).value, 1 / (4 * kPi), 0.05f);
    EXPECT_FALSE(light.sample_le({0.5f, 0.5f}, {0.5f, 0.5f}, SampledWavelengths::rgb_mode()));
    // Non-finite texels become 0.
    Image img(16, 8, Color3(1.0f));
    img(3, 3) = Color3(std::nanf(""), 1, 1);
    EnvironmentMap m(img, EnvLayout::LatLong);
    EXPECT_EQ(m.non_finite_count(), 1u);
    EXPECT_FALSE(m.image().has_non_finite());
}

} // namespace
} // namespace illum

// Light::pdf_le against sample_le: for random photons of every light type, the densities pdf_le gives for
// the photon's ray equal the ones sample_le returned with it (bidirectional MIS relies on that).
#include <gtest/gtest.h>

#include "illum/envmap/environment_map.h"
#include "illum/geometry/disk.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/directional_light.h"
#include "illum/light/image_environment_light.h"
#include "illum/light/point_light.h"
#include "illum/light/spot_light.h"
#include "illum/light/uniform_environment_light.h"
#include "illum/math/rng.h"

namespace illum {
namespace {

const Bounds3f kScene{{-1, -2, 0}, {3, 1, 2}};

// Returns how many of n photons were checked.
int check_pdf_le(const Light& light, int n, std::uint64_t seed, const char* what) {
    PCG32 rng(seed);
    int checked = 0;
    for (int i = 0; i < n; ++i) {
        Point2f u1{rng.uniform_float(), rng.uniform_float()}, u2{rng.uniform_float(), rng.uniform_float()};
        auto s = light.sample_le(u1, u2, SampledWavelengths::rgb_mode());
        if (!s) continue;
        AreaPdf pos(-1);
        SolidAnglePdf dir(-1);
        light.pdf_le(s->ray, s->n, &pos, &dir);
        EXPECT_NEAR(pos.value, s->pdf_pos.value, 1e-4f * s->pdf_pos.value) << what << " photon " << i;
        EXPECT_NEAR(dir.value, s->pdf_dir.value, 2e-3f * s->pdf_dir.value) << what << " photon " << i;
        ++checked;
    }
    return checked;
}

TEST(PdfLe, DiffuseAreaLightOneAndTwoSided) {
    DiskShape disk(Transform::translate({0, 0, 1}), 0, 0.5f, 0, false);
    for (bool two : {false, true}) {
        DiffuseAreaLight light(&disk, Emission(Color3(1, 2, 3)), two);
        EXPECT_GT(check_pdf_le(light, 2000, 11, two ? "two-sided area" : "one-sided area"), 1900);
        // One-sided: nothing behind the emitter.
        if (!two) {
            auto s = light.sample_le({0.3f, 0.6f}, {0.2f, 0.7f}, SampledWavelengths::rgb_mode());
            ASSERT_TRUE(s);
            AreaPdf pos;
            SolidAnglePdf dir;
            light.pdf_le(Ray{s->ray.o, -s->ray.d}, s->n, &pos, &dir);
            EXPECT_EQ(dir.value, 0.0f);
        }
    }
}

TEST(PdfLe, PointAndSpot) {
    PointLight point({1, 2, 3}, Emission(Color3(0.5f, 1, 2)));
    EXPECT_EQ(check_pdf_le(point, 1000, 12, "point"), 1000);
    SpotLight spot({0, 0, 0}, normalize(Vector3f{1, 1, 0}), Emission(Color3(1, 2, 4)), 30 * kPi / 180,
                   5 * kPi / 180);
    EXPECT_EQ(check_pdf_le(spot, 1000, 13, "spot"), 1000);
    // Outside the cone: density zero.
    AreaPdf pos;
    SolidAnglePdf dir;
    spot.pdf_le(Ray{{0, 0, 0}, normalize(Vector3f{-1, 0, 0})}, {}, &pos, &dir);
    EXPECT_EQ(dir.value, 0.0f);
}

TEST(PdfLe, Directional) {
    DirectionalLight light(normalize(Vector3f{1, -1, 2}), Emission(Color3(1, 2, 3)));
    light.preprocess(kScene);
    EXPECT_EQ(check_pdf_le(light, 1000, 14, "directional"), 1000);
    AreaPdf pos;
    SolidAnglePdf dir;
    light.pdf_le(Ray{{0, 0, 0}, normalize(Vector3f{1, 0, 0})}, {}, &pos, &dir);
    EXPECT_EQ(dir.value, 0.0f); // not along the delta direction
}

TEST(PdfLe, UniformEnvironment) {
    UniformEnvironmentLight light(Emission(Color3(0.5f, 1, 2)));
    light.preprocess(kScene);
    EXPECT_EQ(check_pdf_le(light, 1000, 15, "uniform environment"), 1000);
}

TEST(PdfLe, ImageEnvironment) {
    for (EnvLayout layout : {EnvLayout::LatLong, EnvLayout::Octahedral}) {
        int h = 32, w = env_layout_aspect(layout) * h;
        Image img(w, h);
        Vector3f sun = normalize(Vector3f{0.4f, -0.5f, 0.7f});
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                auto d = env_direction(layout, {(x + 0.5f) / w, (y + 0.5f) / h});
                if (!d) continue;
                float sky = 0.1f + std::max(0.0f, d->z);
                img(x, y) =
                    Color3(sky, 0.5f * sky, 2 * sky) + (dot(*d, sun) > 0.95f ? Color3(50.0f) : Color3(0.0f));
            }
        Transform rot = Transform::rotate(30, normalize(Vector3f{1, 2, 3}));
        ImageEnvironmentLight light(EnvironmentMap(std::move(img), layout), rot, 2.0f);
        light.preprocess(kScene);
        EXPECT_GT(check_pdf_le(light, 2000, 16, "image environment"), 1990);
    }
}

} // namespace
} // namespace illum

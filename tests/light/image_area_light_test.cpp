// pbrt-v4's image area light ("diffuse" with "filename"): a constant image renders as the plain area light,
// the image is looked up by (u, 1 - v), power() is π ∫ L dA over the part of the image each primitive covers
// (against photons and against a fine quadrature), pbrt-v4's "power" normalisation, and the errors.
#include <gtest/gtest.h>

#include "illum/geometry/disk.h"
#include "illum/light/area_emission.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/scene/pbrt/parser.h"
#include "image_lights_support.h"
#include "test_support.h"

namespace illum {
namespace {

// A smooth image with a different colour in each corner.
Image gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float u = (x + 0.5f) / w, v = (y + 0.5f) / h;
            img(x, y) = Color3(0.2f + u, 0.3f + v * v, 1.5f - u * v);
        }
    return img;
}

std::string quad_scene(const std::string& area_light) {
    return fmt::format(R"(
LookAt 0 -2.5 1.2  0 0 0.4  0 0 1
Camera "perspective" "float fov" [55]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
AttributeBegin
  {}
  Translate 0 0.5 1
  Rotate 60 1 0 0
  Shape "trianglemesh" "point3 P" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0]
        "point2 uv" [0 0 1 0 1 1 0 1] "integer indices" [0 1 2 0 2 3]
AttributeEnd
)",
                       area_light);
}

TEST(ImageAreaLight, ConstantImageIsThePlainAreaLight) {
    std::string path = test::temp_image(Image(5, 3, Color3(0.5f, 1, 1.5f)), "area_constant");
    test::RenderSetup s;
    s.spp = 8;
    for (bool spectral : {false, true}) {
        s.spectral = spectral;
        Image a = test::render_pbrt(
                      quad_scene(fmt::format(R"(AreaLightSource "diffuse" "string filename" "{}")", path)), s)
                      .image;
        Image b = test::render_pbrt(quad_scene(R"(AreaLightSource "diffuse" "rgb L" [0.5 1 1.5])"), s).image;
        double diff = 0, ref = 0;
        for (std::size_t i = 0; i < a.pixel_count(); ++i)
            for (int c = 0; c < 3; ++c) {
                diff += std::abs(a.data()[i][c] - b.data()[i][c]);
                ref += b.data()[i][c];
            }
        EXPECT_GT(ref, 0);
        EXPECT_LT(diff, 1e-4 * ref) << (spectral ? "spectral" : "rgb");
    }
    std::filesystem::remove(path);
}

// The quad's two triangles each emit π ∫ L dA over their half of the image: against photons, a fine midpoint
// quadrature, and together the whole image's π A mean (up to the bilinear filter's edge clamping).
TEST(ImageAreaLight, PowerIsTheIntegralOverEachPrimitive) {
    Image img = gradient(16, 12);
    std::string path = test::temp_image(img, "area_gradient");
    SceneDesc d = parse_pbrt_string(fmt::format(R"(WorldBegin
AreaLightSource "diffuse" "string filename" "{}" "float scale" 2
Shape "trianglemesh" "point3 P" [0 0 0  2 0 0  2 1 0  0 1 0] "point2 uv" [0 0 1 0 1 1 0 1]
      "integer indices" [0 1 2 0 2 3])",
                                                path),
                                    "<test>", ".");
    auto scene = build_scene(d);
    ASSERT_EQ(scene->lights.size(), 2u);
    Color3 total;
    for (const auto& l : scene->lights) {
        const auto* area = dynamic_cast<const DiffuseAreaLight*>(l.get());
        ASSERT_TRUE(area);
        test::expect_photons_match_power(*area, 100000, 31, "image area light", 2e-3);
        // A 400² midpoint quadrature over the triangle's own area sampling.
        double sum[3] = {};
        const int n = 400;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                AreaShapeSample s = area->shape()->sample_area({(i + 0.5f) / n, (j + 0.5f) / n});
                Radiance3 le = area->emitted(s.n, s.uv, Vector3f(s.n), SampledWavelengths::rgb_mode());
                for (int c = 0; c < 3; ++c) sum[c] += le[c] / s.pdf.value;
            }
        for (int c = 0; c < 3; ++c) {
            double phi = kPiD * sum[c] / (double(n) * n);
            EXPECT_NEAR(area->power()[c], phi, 2e-3 * phi) << c;
        }
        total += area->power().rgb();
    }
    Color3 mean = img.channel_mean();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], 2 * kPiD * 2 * mean[c], 0.02 * 4 * kPiD * mean[c]) << c;
    std::filesystem::remove(path);
}

// pbrt-v4 looks the image up at (u, 1 - v): the image's top row is at v = 1.
TEST(ImageAreaLight, ImageTopRowIsAtVOne) {
    Image img(2, 2);
    img(0, 0) = Color3(1, 0, 0); // top left
    img(1, 1) = Color3(0, 0, 1); // bottom right
    DiskShape disk(Transform(), 0, 1, 0, false);
    DiffuseAreaLight light(&disk, std::make_shared<const Image>(img), 2.0f, false);
    auto lambda = SampledWavelengths::rgb_mode();
    Radiance3 top_left = light.emitted({0, 0, 1}, Point2f{0.1f, 0.9f}, {0, 0, 1}, lambda);
    Radiance3 bottom_right = light.emitted({0, 0, 1}, Point2f{0.9f, 0.1f}, {0, 0, 1}, lambda);
    EXPECT_NEAR(top_left[0], 2, 1e-5);
    EXPECT_NEAR(bottom_right[2], 2, 1e-5);
    EXPECT_EQ(light.emitted({0, 0, 1}, Point2f{0.1f, 0.9f}, {0, 0, -1}, lambda)[0], 0); // one-sided
}

// pbrt-v4's "power" with an image: P / (π A mean(lum)) per primitive. A disk's uv (u = φ / φmax) spans an
// image varying in u only evenly, so its power is then P.
TEST(ImageAreaLight, PowerNormalisation) {
    Image img(32, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 32; ++x) img(x, y) = Color3(0.5f + 0.4f * std::sin(2 * kPi * (x + 0.5f) / 32));
    std::string path = test::temp_image(img, "area_power");
    SceneDesc d = parse_pbrt_string(fmt::format(R"(WorldBegin
AreaLightSource "diffuse" "string filename" "{}" "float power" 7 "bool twosided" true
Shape "disk" "float radius" 0.7)",
                                                path),
                                    "<test>", ".");
    auto scene = build_scene(d);
    ASSERT_EQ(scene->lights.size(), 1u);
    EXPECT_NEAR(scene->lights[0]->power()[0], 7, 7e-3);
    std::filesystem::remove(path);
}

TEST(ImageAreaLight, BadInput) {
    // "L" with "filename" (pbrt-v4 refuses it), at the position of "L".
    SceneDesc d = parse_pbrt_string(R"(WorldBegin
AreaLightSource "diffuse" "string filename" "x.exr" "rgb L" [1 1 1]
Shape "sphere")",
                                    "<test>", ".");
    try {
        build_scene(d);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("<test>:2:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("\"L\" and \"filename\""), std::string::npos) << e.what();
    }
    // A missing image: an error naming the file at the parameter.
    SceneDesc m = parse_pbrt_string(R"(WorldBegin
AreaLightSource "diffuse" "string filename" "no_such_area_image.exr"
Shape "sphere")",
                                    "<test>", ".");
    try {
        build_scene(m);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("<test>:2:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no_such_area_image.exr"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum

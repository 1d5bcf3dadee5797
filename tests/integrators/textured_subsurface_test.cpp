// Textured coefficients of pbrt-v4's "subsurface" material (issue "Participating media"): volpath evaluates
// them where a path enters the shape (medium/entry_medium.h) and walks the interior with those. A constant
// texture gives the plain material's image; a two-valued texture gives, where the camera's paths enter
// each part, the image of the plain material with that part's value (the sphere is convex and alone in a
// uniform environment, so a camera path enters it once); negative texels clamp as pbrt-v4 clamps.
// Tolerances: 4.5 combined standard errors over the compared pixels (fixed seeds).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5;

RenderSetup volpath(int spp, bool spectral, std::uint64_t seed = 7) {
    return test::independent_setup("volpath", spp, spectral, -2, seed);
}

// A subsurface sphere (its pole along y: v < 1/2, the lower hemisphere, is a checkerboard's "tex1" with
// "vscale" 2) in a uniform environment, seen along -z; box filter, so a pixel's samples stay in it.
std::string sphere_scene(const std::string& textures, const std::string& material) {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [26]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box"
Sampler "independent"
Integrator "volpath" "integer maxdepth" [-1]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
{}
AttributeBegin
  {}
  Rotate -90 1 0 0
  Shape "sphere" "float radius" [1]
AttributeEnd
)",
                       textures, material);
}

// A checkerboard texture "name": a below the equator, b above.
std::string halves(const std::string& name, const std::string& a, const std::string& b) {
    return fmt::format(R"(Texture "{}" "spectrum" "checkerboard" "float uscale" [1] "float vscale" [2]
  "rgb tex1" [{}] "rgb tex2" [{}]
)",
                       name, a, b);
}

struct Region {
    double mean = 0, standard_error = 0;
};
// The mean over image rows [y0, y1) of channel c of a - b (b: none), with its standard error from the
// pixels' spread (a difference of two renders of the same view cancels the image's own variation).
Region rows_mean(const Image& a, const Image* b, int c, int y0, int y1) {
    double s = 0, s2 = 0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < a.width(); ++x) {
            double v = a.at(x, y)[c] - (b ? b->at(x, y)[c] : 0.0f);
            s += v;
            s2 += v * v;
            ++n;
        }
    double m = s / n;
    return {m, std::sqrt(std::max(0.0, s2 / n - m * m) / (n - 1))};
}

void expect_same_image(const RenderResult& a, const RenderResult& b, const std::string& what) {
    ASSERT_EQ(a.image.pixel_count(), b.image.pixel_count());
    for (std::size_t i = 0; i < a.image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(a.image.data()[i][c], b.image.data()[i][c]) << what << " pixel " << i;
}

// (1) A constant texture is the plain number: the same image, bit for bit in RGB mode (the same floats
// reach the walk) and for sigma_a/sigma_s in spectral mode; reflectance/mfp in spectral mode inverts at
// the exact wavelengths where the plain material interpolates a 1 nm table, so there the means agree to
// the table's rounding (and the few walk decisions it flips).
TEST(TexturedSubsurface, ConstantTextureIsThePlainMaterial) {
    const std::string sigma_tex = R"(Texture "a" "spectrum" "constant" "rgb value" [0.2 0.4 0.8]
Texture "s" "spectrum" "constant" "rgb value" [4 3 2])";
    const std::string refl_tex = R"(Texture "r" "spectrum" "constant" "rgb value" [0.8 0.5 0.2]
Texture "l" "spectrum" "constant" "rgb value" [0.3 0.2 0.5])";
    for (bool spectral : {false, true}) {
        RenderResult plain = render_pbrt(
            sphere_scene("", R"(Material "subsurface" "rgb sigma_a" [0.2 0.4 0.8] "rgb sigma_s" [4 3 2]
                                "float scale" [2])"),
            volpath(4, spectral));
        RenderResult textured = render_pbrt(
            sphere_scene(sigma_tex, R"(Material "subsurface" "texture sigma_a" "a" "texture sigma_s" "s"
                                       "float scale" [2])"),
            volpath(4, spectral));
        expect_same_image(plain, textured, spectral ? "sigma, spectral" : "sigma, RGB");

        plain = render_pbrt(sphere_scene("", R"(Material "subsurface" "rgb reflectance" [0.8 0.5 0.2]
                                                "rgb mfp" [0.3 0.2 0.5] "float g" [0.3])"),
                            volpath(16, spectral));
        textured = render_pbrt(sphere_scene(refl_tex, R"(Material "subsurface" "texture reflectance" "r"
                                                         "texture mfp" "l" "float g" [0.3])"),
                               volpath(16, spectral));
        if (!spectral) {
            expect_same_image(plain, textured, "reflectance, RGB");
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            Region p = rows_mean(plain.image, nullptr, c, 0, 16),
                   t = rows_mean(textured.image, nullptr, c, 0, 16);
            std::printf("reflectance/mfp spectral ch %d: plain %.6f textured %.6f\n", c, p.mean, t.mean);
            EXPECT_NEAR(t.mean, p.mean, 2e-3 * p.mean) << "channel " << c;
        }
    }
}

// (2) A two-valued texture: the rows where the camera's paths enter the lower half match the plain
// material with the lower value, the upper rows the upper value (the two rows at the seam, whose pixels'
// filtered texture mixes both, are left out).
void expect_halves(const std::string& textures, const std::string& textured_material,
                   const std::string& lower_material, const std::string& upper_material, bool spectral,
                   const std::string& what) {
    const int spp = 64;
    RenderResult t = render_pbrt(sphere_scene(textures, textured_material), volpath(spp, spectral, 7));
    RenderResult lo = render_pbrt(sphere_scene("", lower_material), volpath(spp, spectral, 1234));
    RenderResult up = render_pbrt(sphere_scene("", upper_material), volpath(spp, spectral, 99));
    EXPECT_EQ(t.nonfinite_samples, 0u);
    // Image row 0 is the top: rows 0-6 see the upper hemisphere, 9-15 the lower.
    double wrong_upper = 0, wrong_lower = 0; // the other value's largest distance, in standard errors
    for (int c = 0; c < 3; ++c) {
        Region u = rows_mean(t.image, &up.image, c, 0, 7), l = rows_mean(t.image, &lo.image, c, 9, 16);
        Region wu = rows_mean(t.image, &lo.image, c, 0, 7), wl = rows_mean(t.image, &up.image, c, 9, 16);
        std::printf("%s ch %d: upper - plain upper %+.5f +- %.2g (- plain lower %+.5f), lower - plain lower "
                    "%+.5f +- %.2g (- plain upper %+.5f)\n",
                    what.c_str(), c, u.mean, u.standard_error, wu.mean, l.mean, l.standard_error, wl.mean);
        EXPECT_NEAR(u.mean, 0, kSigmas * u.standard_error) << what << " upper, channel " << c;
        EXPECT_NEAR(l.mean, 0, kSigmas * l.standard_error) << what << " lower, channel " << c;
        wrong_upper = std::max(wrong_upper, std::abs(wu.mean) / wu.standard_error);
        wrong_lower = std::max(wrong_lower, std::abs(wl.mean) / wl.standard_error);
    }
    // The test can fail: the other half's material is far outside the tolerance.
    EXPECT_GT(wrong_upper, 2 * kSigmas) << what;
    EXPECT_GT(wrong_lower, 2 * kSigmas) << what;
}

TEST(TexturedSubsurface, TwoValuedSigmaTextureGivesEachHalfItsMaterial) {
    for (bool spectral : {false, true})
        expect_halves(halves("a", "0.2 0.4 0.8", "1.5 0.3 0.05") + halves("s", "4 3 2", "1 2 6"),
                      R"(Material "subsurface" "texture sigma_a" "a" "texture sigma_s" "s")",
                      R"(Material "subsurface" "rgb sigma_a" [0.2 0.4 0.8] "rgb sigma_s" [4 3 2])",
                      R"(Material "subsurface" "rgb sigma_a" [1.5 0.3 0.05] "rgb sigma_s" [1 2 6])", spectral,
                      spectral ? "sigma halves, spectral" : "sigma halves, RGB");
}

TEST(TexturedSubsurface, TwoValuedReflectanceTextureGivesEachHalfItsMaterial) {
    for (bool spectral : {false, true})
        expect_halves(halves("r", "0.9 0.6 0.2", "0.2 0.5 0.95"),
                      R"(Material "subsurface" "texture reflectance" "r" "rgb mfp" [0.2 0.3 0.4])",
                      R"(Material "subsurface" "rgb reflectance" [0.9 0.6 0.2] "rgb mfp" [0.2 0.3 0.4])",
                      R"(Material "subsurface" "rgb reflectance" [0.2 0.5 0.95] "rgb mfp" [0.2 0.3 0.4])",
                      spectral, spectral ? "reflectance halves, spectral" : "reflectance halves, RGB");
}

// An image map (marble-like use): scenes/texture-filtering/checker.png, 8-bit checks of reflectance 0.05 and
// 0.8 (32 × 32 over the sphere's uv): the sphere's mean lies strictly between the plain materials'.
TEST(TexturedSubsurface, ImageMapReflectanceLiesBetweenItsTexels) {
    const std::string image = std::string(ILLUM_SOURCE_DIR) + "/scenes/texture-filtering/checker.png";
    RenderResult t = render_pbrt(
        sphere_scene(fmt::format(R"(Texture "img" "spectrum" "imagemap" "string filename" "{}")", image),
                     R"(Material "subsurface" "texture reflectance" "img" "rgb mfp" [0.1 0.1 0.1])"),
        volpath(16, false, 7));
    RenderResult dark = render_pbrt(
        sphere_scene("",
                     R"(Material "subsurface" "rgb reflectance" [0.05 0.05 0.05] "rgb mfp" [0.1 0.1 0.1])"),
        volpath(16, false, 8));
    RenderResult light = render_pbrt(
        sphere_scene("", R"(Material "subsurface" "rgb reflectance" [0.8 0.8 0.8] "rgb mfp" [0.1 0.1 0.1])"),
        volpath(16, false, 9));
    EXPECT_EQ(t.nonfinite_samples, 0u);
    for (int c = 0; c < 3; ++c) {
        Region a = rows_mean(dark.image, nullptr, c, 0, 16), m = rows_mean(t.image, &dark.image, c, 0, 16);
        Region b = rows_mean(light.image, &t.image, c, 0, 16);
        std::printf(
            "image map ch %d: dark %.5f, textured - dark %+.5f +- %.2g, light - textured %+.5f +- %.2g\n", c,
            a.mean, m.mean, m.standard_error, b.mean, b.standard_error);
        EXPECT_GT(m.mean, kSigmas * m.standard_error) << "channel " << c;
        EXPECT_GT(b.mean, kSigmas * b.standard_error) << "channel " << c;
    }
}

// (3) Negative texels clamp as pbrt-v4's GetBSSRDF clamps them (textures are only known at render time;
// negative constants stay errors): σ = max(0, scale · value), so a negative sigma_a is a zero one; a mean
// free path at or below zero (pbrt-v4: a division by zero) is kept at 1e-8, finite.
TEST(TexturedSubsurface, NegativeTexelsClampAsPbrt) {
    const std::string base = R"(Texture "c" "spectrum" "constant" "rgb value" [1 1 1]
Texture "s" "spectrum" "constant" "rgb value" [4 3 2]
)";
    RenderResult neg = render_pbrt(
        sphere_scene(base + R"(Texture "neg" "spectrum" "scale" "texture tex" "c" "float scale" [-0.5])",
                     R"(Material "subsurface" "texture sigma_a" "neg" "texture sigma_s" "s")"),
        volpath(4, false));
    RenderResult zero = render_pbrt(
        sphere_scene(base + R"(Texture "zero" "spectrum" "scale" "texture tex" "c" "float scale" [0])",
                     R"(Material "subsurface" "texture sigma_a" "zero" "texture sigma_s" "s")"),
        volpath(4, false));
    expect_same_image(neg, zero, "negative sigma_a");

    RenderResult bad_mfp = render_pbrt(
        sphere_scene(base + R"(Texture "neg" "spectrum" "scale" "texture tex" "c" "float scale" [-1])",
                     R"(Material "subsurface" "rgb reflectance" [0.5 0.5 0.5] "texture mfp" "neg")"),
        volpath(4, true));
    RenderResult tiny_mfp = render_pbrt(
        sphere_scene(base + R"(Texture "tiny" "spectrum" "scale" "texture tex" "c" "float scale" [1e-8])",
                     R"(Material "subsurface" "rgb reflectance" [0.5 0.5 0.5] "texture mfp" "tiny")"),
        volpath(4, true));
    EXPECT_EQ(bad_mfp.nonfinite_samples, 0u);
    EXPECT_FALSE(bad_mfp.image.has_non_finite());
    expect_same_image(bad_mfp, tiny_mfp, "non-positive mfp");

    // A negative constant is still an error at its position.
    try {
        render_pbrt(sphere_scene(base, R"(Material "subsurface" "texture sigma_a" "c"
  "rgb sigma_s" [-1 1 1])"),
                    volpath(1, false));
        ADD_FAILURE() << "a negative constant sigma_s was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("<test>:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("sigma_s"), std::string::npos) << e.what();
    }
}

// The scene builds without the old "not supported" warning, and so does the committed comparison scene,
// which renders finite.
TEST(TexturedSubsurface, BuildsWithoutWarnings) {
    SceneDesc desc = parse_pbrt_string(
        sphere_scene(halves("r", "0.9 0.6 0.2", "0.2 0.5 0.95"),
                     R"(Material "subsurface" "texture reflectance" "r" "rgb mfp" [0.2 0.3 0.4])"),
        "<test>", ".");
    auto scene = build_scene(desc);
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();

    SceneDesc file =
        parse_pbrt_file(std::string(ILLUM_SOURCE_DIR) + "/scenes/media/subsurface-textured.pbrt");
    file.set_film_resolution(16, 12);
    auto built = build_scene(file);
    EXPECT_TRUE(built->warnings.empty()) << built->warnings.front();
    auto integrator = make_integrator("volpath", *built, built->request.max_depth);
    RenderOptions opt;
    opt.spp = 2;
    opt.quiet = true;
    opt.spectral = true;
    RenderResult r = render(*built, *integrator, opt);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    EXPECT_FALSE(r.image.has_non_finite());
}

// The other integrators that walk the interior (bdpt and vcm through path_vertex.h's walk and connections,
// lightpath, and volpath's caustics by light tracing) evaluate a textured medium where each subpath enters
// it: with a constant texture, the plain material's image, bit for bit. A rough boundary (connections
// and next-event estimation through it), a floor, a spot light and a small area light.
TEST(TexturedSubsurface, OtherIntegratorsWithAConstantTextureMatchThePlainMaterial) {
    auto scene = [](const std::string& textures, const std::string& material) {
        return fmt::format(R"(
LookAt 0 2 5  0 0.5 0  0 1 0
Camera "perspective" "float fov" [30]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box"
Sampler "independent"
Integrator "volpath" "integer maxdepth" [8]
WorldBegin
LightSource "spot" "point3 from" [2 4 2] "point3 to" [0 0 0] "float coneangle" [30] "rgb I" [20 20 20]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [8 8 8]
  Translate -2 3 1
  Shape "sphere" "float radius" [0.2]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "point3 P" [-5 0 -5  -5 0 5  5 0 5  5 0 -5] "integer indices" [0 1 2 0 2 3]
{}
AttributeBegin
  {}
  Translate 0 0.8 0
  Shape "sphere" "float radius" [0.8]
AttributeEnd
)",
                           textures, material);
    };
    const std::string plain = scene("", R"(Material "subsurface" "rgb sigma_a" [0.2 0.4 0.8]
        "rgb sigma_s" [4 3 2] "float roughness" [0.2])");
    const std::string textured = scene(R"(Texture "a" "spectrum" "constant" "rgb value" [0.2 0.4 0.8]
Texture "s" "spectrum" "constant" "rgb value" [4 3 2])",
                                       R"(Material "subsurface" "texture sigma_a" "a" "texture sigma_s" "s"
        "float roughness" [0.2])");
    const std::string smooth_plain = scene("", R"(Material "subsurface" "rgb sigma_a" [0.2 0.4 0.8]
        "rgb sigma_s" [4 3 2])");
    const std::string smooth_textured =
        scene(R"(Texture "a" "spectrum" "constant" "rgb value" [0.2 0.4 0.8]
Texture "s" "spectrum" "constant" "rgb value" [4 3 2])",
              R"(Material "subsurface" "texture sigma_a" "a" "texture sigma_s" "s")");
    const std::string other_textured =
        scene(R"(Texture "a" "spectrum" "constant" "rgb value" [2 2 2]
Texture "s" "spectrum" "constant" "rgb value" [4 3 2])",
              R"(Material "subsurface" "texture sigma_a" "a" "texture sigma_s" "s"
        "float roughness" [0.2])");
    for (const char* integrator : {"bdpt", "vcm", "lightpath", "volpath"})
        for (bool spectral : {false, true}) {
            RenderSetup s = volpath(4, spectral);
            s.integrator = integrator;
            std::string what = fmt::format("{}{}", integrator, spectral ? ", spectral" : "");
            expect_same_image(render_pbrt(plain, s), render_pbrt(textured, s), what);
            // Smooth: volpath leaves the caustics through the sphere to light tracing.
            expect_same_image(render_pbrt(smooth_plain, s), render_pbrt(smooth_textured, s),
                              what + ", smooth");
            // The texture is what the walk reads: another value gives another image.
            Image other = render_pbrt(other_textured, s).image, base = render_pbrt(plain, s).image;
            double d = 0, sum = 0;
            for (std::size_t i = 0; i < base.pixel_count(); ++i) {
                d += std::abs(other.data()[i].r - base.data()[i].r);
                sum += base.data()[i].r;
            }
            std::printf("%s: image sum %.4g, |other texture - plain| %.4g\n", what.c_str(), sum, d);
            EXPECT_GT(d, 0.0) << what;
        }
}

} // namespace
} // namespace illum

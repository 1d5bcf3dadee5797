// The film's pbrt-v4 parameters: cropwindow and pixelbounds (the kept pixels equal those of the full
// render bit for bit: each pixel's samples come from (seed, pixel, index) and the camera projects onto the
// full resolution), maxcomponentvalue (each sample's largest sensor component limited, its hue kept) and
// their errors.
#include <gtest/gtest.h>

#include <algorithm>

#include "illum/camera/film.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

// A small scene with structure everywhere (a lit sphere over a floor) at 24 x 16.
std::string scene_with_film(const std::string& film_params, const std::string& options = "") {
    return options + R"(LookAt 0 1.5 -4  0 0.3 0  0 1 0
Camera "perspective" "float fov" 50
Film "rgb" "integer xresolution" 24 "integer yresolution" 16 )" +
           film_params + R"(
Sampler "sobol" "integer pixelsamples" 4
PixelFilter "gaussian"
WorldBegin
LightSource "point" "rgb I" [8 8 8] "point3 from" [1 3 -2]
LightSource "infinite" "rgb L" [0.1 0.1 0.1]
Material "diffuse" "rgb reflectance" [0.7 0.5 0.3]
Shape "sphere" "float radius" 0.6
Material "conductor" "float roughness" 0.2
Shape "bilinearmesh" "point3 P" [-3 -0.6 -3  3 -0.6 -3  -3 -0.6 3  3 -0.6 3]
)";
}

PixelBounds bounds_of(const std::string& film_params) {
    return build_scene(parse_pbrt_string(scene_with_film(film_params), "<test>", "."))->pixel_bounds;
}

void expect_bounds(const PixelBounds& b, int x0, int y0, int x1, int y1) {
    EXPECT_EQ(b.x0, x0);
    EXPECT_EQ(b.y0, y0);
    EXPECT_EQ(b.x1, x1);
    EXPECT_EQ(b.y1, y1);
}

TEST(FilmWindow, CropWindowRoundsUpAsPbrtV4) {
    // 24 x 16: x [ceil(24·0.1), ceil(24·0.55)) = [3, 14), y [ceil(16·0.3), ceil(16·0.8)) = [5, 13).
    expect_bounds(bounds_of("\"float cropwindow\" [0.1 0.55 0.3 0.8]"), 3, 5, 14, 13);
    // Pairs in either order, as pbrt-v4 takes them.
    expect_bounds(bounds_of("\"float cropwindow\" [0.55 0.1 0.8 0.3]"), 3, 5, 14, 13);
    expect_bounds(bounds_of("\"integer pixelbounds\" [2 9 4 16]"), 2, 4, 9, 16);
    // The crop window wins over pixel bounds, as in pbrt-v4.
    expect_bounds(bounds_of("\"integer pixelbounds\" [2 9 4 16] \"float cropwindow\" [0 0.5 0 0.5]"), 0, 0,
                  12, 8);
    expect_bounds(bounds_of(""), 0, 0, 24, 16);
}

Image crop_of(const Image& full, int x0, int y0, int x1, int y1) {
    return crop(full, PixelBounds{x0, y0, x1, y1});
}

TEST(FilmWindow, CroppedRendersAreTheFullRendersPixelsExactly) {
    for (const char* integrator : {"path", "volpath", "lightpath", "bdpt"}) {
        test::RenderSetup setup;
        setup.integrator = integrator;
        setup.spp = 4;
        setup.seed = 3;
        Image full = test::render_pbrt(scene_with_film(""), setup).image;
        ASSERT_EQ(full.width(), 24);
        Image cropped =
            test::render_pbrt(scene_with_film("\"float cropwindow\" [0.1 0.55 0.3 0.8]"), setup).image;
        EXPECT_EQ(cropped, crop_of(full, 3, 5, 14, 13)) << integrator;
        Image bounded = test::render_pbrt(scene_with_film("\"integer pixelbounds\" [2 9 4 16]"), setup).image;
        EXPECT_EQ(bounded, crop_of(full, 2, 4, 9, 16)) << integrator;
    }
}

TEST(FilmWindow, BadWindowsArePositionedErrors) {
    auto build = [](const std::string& film) {
        return [film] { build_scene(parse_pbrt_string(scene_with_film(film), "f.pbrt", ".")); };
    };
    test::expect_error(build("\"float cropwindow\" [0 1.2 0 1]"), "f.pbrt:3:", "outside [0, 1]");
    test::expect_error(build("\"float cropwindow\" [-0.1 1 0 1]"), "f.pbrt:3:", "outside [0, 1]");
    test::expect_error(build("\"float cropwindow\" [0.5 0.5 0 1]"), "f.pbrt:3:", "keeps no pixel");
    test::expect_error(build("\"float cropwindow\" [0 1 0]"), "f.pbrt:3:", "needs 4 values");
    test::expect_error(build("\"integer pixelbounds\" [0 25 0 16]"), "f.pbrt:3:", "outside the 24x16 film");
    test::expect_error(build("\"integer pixelbounds\" [-1 5 0 16]"), "f.pbrt:3:", "outside the 24x16 film");
    test::expect_error(build("\"integer pixelbounds\" [3 3 0 16]"), "f.pbrt:3:", "keep no pixel");
    test::expect_error(build("\"float maxcomponentvalue\" 0"), "f.pbrt:3:", "must be positive");
}

// A camera that sees only an emitter of radiance L: every sample is L (one bounce, no noise).
std::string emitter_scene(const std::string& rgb, const std::string& film_params) {
    return R"(Camera "orthographic"
Film "rgb" "integer xresolution" 4 "integer yresolution" 4 )" +
           film_params + R"(
WorldBegin
AreaLightSource "diffuse" "rgb L" [)" +
           rgb + R"(] "bool twosided" true
Shape "bilinearmesh" "point3 P" [-5 -5 1  5 -5 1  -5 5 1  5 5 1]
)";
}

TEST(FilmWindow, MaxComponentValueScalesFirefliesDownKeepingTheirHue) {
    // L = (40, 10, 2) in sRGB: its XYZ (the sensor values of pbrt-v4's cie1931 sensor) has the largest
    // component X = 0.4124·40 + 0.3576·10 + 0.1805·2 ≈ 20.43; maxcomponentvalue 5 scales L by 5 / X.
    const RGBColorSpace& srgb = RGBColorSpace::srgb();
    const double* m = srgb.xyz_from_rgb_matrix_f64();
    Color3 l(40, 10, 2);
    double xyz[3];
    for (int i = 0; i < 3; ++i) xyz[i] = m[3 * i] * l.r + m[3 * i + 1] * l.g + m[3 * i + 2] * l.b;
    double largest = std::max({xyz[0], xyz[1], xyz[2]});
    ASSERT_NEAR(largest, 20.43, 0.01);
    Image clamped = test::render_pbrt(emitter_scene("40 10 2", "\"float maxcomponentvalue\" 5")).image;
    Image free = test::render_pbrt(emitter_scene("40 10 2", "")).image;
    Image below = test::render_pbrt(emitter_scene("40 10 2", "\"float maxcomponentvalue\" 25")).image;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(free(1, 2)[c], l[c], 1e-4f * l[c]);
        EXPECT_NEAR(clamped(1, 2)[c], l[c] * 5 / largest, 1e-5f * l[c]);
        EXPECT_EQ(below(1, 2)[c], free(1, 2)[c]); // under the limit: untouched
    }
    // Spectral mode: each sample's own XYZ is limited, so the pixel's largest XYZ component is at most 5.
    test::RenderSetup spectral;
    spectral.spectral = true;
    Image s = test::render_pbrt(emitter_scene("40 10 2", "\"float maxcomponentvalue\" 5"), spectral).image;
    const double* to_xyz = srgb.xyz_from_rgb_matrix_f64();
    Color3 p = s(2, 2);
    double x = to_xyz[0] * p.r + to_xyz[1] * p.g + to_xyz[2] * p.b;
    EXPECT_LE(x, 5 * (1 + 1e-4));
    EXPECT_GT(x, 1); // clamped, not black
}

// The film's limit holds for every integrator that adds camera samples to it, whatever the strategy that
// found the light: the path tracer, BDPT (s = 0) and VCM (its camera pass). SPPM's image is not limited,
// as in pbrt-v4. RGB and spectral mode.
TEST(FilmWindow, MaxComponentValueHoldsForTheBidirectionalIntegrators) {
    for (bool spectral : {false, true})
        for (const char* integrator : {"path", "bdpt", "vcm"}) {
            test::RenderSetup setup;
            setup.integrator = integrator;
            setup.spectral = spectral;
            setup.spp = 4;
            Image free = test::render_pbrt(emitter_scene("40 10 2", ""), setup).image;
            Image clamped =
                test::render_pbrt(emitter_scene("40 10 2", "\"float maxcomponentvalue\" 5"), setup).image;
            const double* to_xyz = RGBColorSpace::srgb().xyz_from_rgb_matrix_f64();
            Color3 p = clamped(2, 2), f = free(2, 2);
            double x = to_xyz[0] * p.r + to_xyz[1] * p.g + to_xyz[2] * p.b;
            double x_free = to_xyz[0] * f.r + to_xyz[1] * f.g + to_xyz[2] * f.b;
            EXPECT_GT(x_free, 15) << integrator << (spectral ? " spectral" : " rgb");
            EXPECT_LE(x, 5 * (1 + 1e-4)) << integrator << (spectral ? " spectral" : " rgb");
            EXPECT_GT(x, 1) << integrator << (spectral ? " spectral" : " rgb"); // limited, not black
        }
}

} // namespace
} // namespace illum

#include "illum/analysis/light_checks.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/analysis/check_render.h"
#include "illum/envmap/layout.h"
#include "illum/geometry/disk.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/goniometric_light.h"
#include "illum/light/image_environment_light.h"
#include "illum/light/portal_environment_light.h"
#include "illum/light/projection_light.h"
#include "illum/math/rng.h"

namespace illum {

namespace {

// A scene holding `world` and a unit sphere at the origin (so distant and infinite lights have bounds),
// its lights preprocessed against them.
std::unique_ptr<Scene> light_scene(const std::string& world) {
    return scene_from_text(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective"
Film "rgb" "integer xresolution" [4] "integer yresolution" [4]
WorldBegin
)" + world + "\nShape \"sphere\" \"float radius\" [1]\n");
}

double scene_radius(const Scene& scene) {
    Point3f c;
    float r;
    scene.accelerator.bounds().bounding_sphere(&c, &r);
    return r;
}

// A smooth latitude-longitude sky: brighter towards +z, tinted, with a gentle azimuthal variation.
Image sky(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double t = kPiD * (y + 0.5) / h, p = 2 * kPiD * (x + 0.5) / w;
            float v = float(1 + 0.6 * std::cos(t) + 0.2 * std::sin(t) * std::cos(p));
            img(x, y) = Color3(0.6f * v, 0.8f * v, v);
        }
    return img;
}

} // namespace

VerifyCheck check_light_power(const Light& light, const std::string& name, const std::string& closed_form,
                              Color3 expected, int photons, const VerifyOptions& o, double allowance) {
    PCG32 rng(o.seed, 17);
    double sum[3] = {}, sum2[3] = {};
    for (int i = 0; i < photons; ++i) {
        Point2f u1{rng.uniform_float(), rng.uniform_float()}, u2{rng.uniform_float(), rng.uniform_float()};
        auto s = light.sample_le(u1, u2, SampledWavelengths::rgb_mode());
        for (int c = 0; c < 3; ++c) {
            double f = s ? double(s->flux[c]) : 0.0;
            sum[c] += f;
            sum2[c] += f * f;
        }
    }
    Estimate m[3];
    double e[3];
    for (int c = 0; c < 3; ++c) {
        double mean = sum[c] / photons;
        m[c] = {mean, std::sqrt(std::max(0.0, sum2[c] / photons - mean * mean) / (photons - 1))};
        e[c] = expected[c];
    }
    return judge_rgb("lights", name + ": mean photon flux of sample_le", closed_form, e, m, allowance, o,
                     fmt::format("{} photons", photons));
}

VerifyCheck check_light_power_method(const Light& light, const std::string& name,
                                     const std::string& closed_form, Color3 expected, const VerifyOptions& o,
                                     double allowance) {
    Color3 p = light.power().rgb();
    Estimate m[3] = {{p.r, 0}, {p.g, 0}, {p.b, 0}};
    double e[3] = {expected.r, expected.g, expected.b};
    return judge_rgb("lights", name + ": power()", closed_form, e, m, allowance, o);
}

std::vector<VerifyCheck> check_light_powers(const VerifyOptions& o) {
    std::vector<VerifyCheck> out;
    const int photons = 200000;
    auto both = [&](const Light& light, const std::string& name, const std::string& form, Color3 expected) {
        out.push_back(check_light_power(light, name, form, expected, photons, o));
        out.push_back(check_light_power_method(light, name, form, expected, o));
    };
    const Color3 I(0.5f, 1, 2);
    {
        auto s = light_scene(R"(LightSource "point" "point3 from" [0 0 3] "rgb I" [0.5 1 2])");
        both(*s->lights.at(0), "point light", "Φ = 4π I", I * float(4 * kPiD));
        auto p =
            light_scene(R"(LightSource "point" "point3 from" [0 0 3] "rgb I" [1 1 1] "float power" [10])");
        both(*p->lights.at(0), "point light given \"power\" 10", "Φ = power", Color3(10.0f));
    }
    {
        double cone = 30, delta = 5, ce = std::cos(cone * kPiD / 180),
               cs = std::cos((cone - delta) * kPiD / 180);
        auto s = light_scene(
            R"(LightSource "spot" "point3 from" [0 0 3] "point3 to" [1 0 0] "float coneangle" [30] "float conedeltaangle" [5] "rgb I" [0.5 1 2])");
        both(*s->lights.at(0), "spot light 30°, delta 5°", "Φ = 2π I [(1 - cos θs) + (cos θs - cos θe)/2]",
             I * float(2 * kPiD * ((1 - cs) + (cs - ce) / 2)));
    }
    {
        auto s = light_scene(
            R"(LightSource "distant" "point3 from" [1 -1 2] "point3 to" [0 0 0] "rgb L" [1 2 3])");
        double r = scene_radius(*s);
        both(*s->lights.at(0), "distant light", "Φ = π r² E (r: scene radius)",
             Color3(1, 2, 3) * float(kPiD * r * r));
    }
    {
        auto s = light_scene(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 2 3]
Translate 0 0 2
Shape "disk" "float radius" [0.5]
AttributeEnd)");
        both(*s->lights.at(0), "one-sided disk area light r = 0.5", "Φ = π L A = π L π r²",
             Color3(1, 2, 3) * float(kPiD * kPiD * 0.25));
        auto t = light_scene(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 2 3] "bool twosided" true
Translate 0 0 3
Shape "sphere" "float radius" [0.3]
AttributeEnd)");
        both(*t->lights.at(0), "two-sided sphere area light R = 0.3", "Φ = 2 π L 4π R²",
             Color3(1, 2, 3) * float(2 * kPiD * 4 * kPiD * 0.09));
    }
    {
        auto s = light_scene(R"(LightSource "infinite" "rgb L" [0.5 1 2])");
        double r = scene_radius(*s);
        both(*s->lights.at(0), "uniform infinite light", "Φ = 4π L π r² (r: scene radius)",
             I * float(4 * kPiD * kPiD * r * r));
    }
    {
        const int w = 64, h = 32;
        Image img = sky(w, h);
        double integral[3] = {};
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double omega = 2 * kPiD / w * (std::cos(kPiD * y / h) - std::cos(kPiD * (y + 1) / h));
                for (int c = 0; c < 3; ++c) integral[c] += img(x, y)[c] * omega;
            }
        auto s = light_scene("");
        ImageEnvironmentLight light(EnvironmentMap(img, EnvLayout::LatLong), Transform::rotate(30, {1, 0, 0}),
                                    2.0f);
        light.preprocess(s->accelerator.bounds());
        double r = scene_radius(*s), k = 2 * kPiD * r * r;
        Color3 phi(float(k * integral[0]), float(k * integral[1]), float(k * integral[2]));
        // The photons see the bilinearly filtered map, whose integral differs from the texel sum by the
        // filter's curvature error: below this estimate's noise for the smooth sky (|Δ| = 7·10⁻⁵ relative,
        // σ = 1.3·10⁻⁴ at the default seed); 10⁻³ allowed.
        out.push_back(check_light_power(light, "image infinite light (64x32 sky, scale 2)",
                                        "Φ = s π r² Σ L Ω (latitude-longitude texels)", phi, photons, o,
                                        1e-3));
        out.push_back(check_light_power_method(light, "image infinite light (64x32 sky, scale 2)",
                                               "Φ = s π r² Σ L Ω (latitude-longitude texels)", phi, o));
    }
    {
        // Goniometric: an equal-area image brighter towards its +z; Φ = 4π I mean(Y), every texel of the
        // map covering 4π / N².
        const int n = 32;
        Image img(n, n);
        double sum = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                Vector3f d = *env_direction(EnvLayout::Octahedral, {(x + 0.5f) / n, (y + 0.5f) / n});
                float v = 0.2f + std::max(0.0f, d.z) + 0.3f * d.x * d.x;
                img(x, y) = Color3(v);
                sum += v;
            }
        GoniometricLight light(Transform::rotate(30, {1, 0, 0}), Emission(Color3(0.5f, 1, 2)), img);
        both(light, "goniometric light (32² equal-area image)", "Φ = 4π I mean(Y)",
             I * float(4 * kPiD * sum / (n * n)));
    }
    {
        // Projection of a constant image: the pyramid's solid angle 4 asin(sx sy / √((1 + sx²)(1 + sy²))).
        const float fov = 50;
        ProjectionLight light(Transform::rotate(20, {0, 1, 0}), Image(6, 3, Color3(0.5f, 1, 2)), 1.5f, fov);
        double t = std::tan(fov / 2 * kPiD / 180), sx = 2 * t, sy = t;
        double omega = 4 * std::asin(sx * sy / std::sqrt((1 + sx * sx) * (1 + sy * sy)));
        both(light, "projection light (constant 6x3 image, fov 50)",
             "Φ = s L 4 asin(sx sy / √((1+sx²)(1+sy²)))", I * float(1.5 * omega));
    }
    {
        // An image area light on a disk whose image varies along u (= φ / 2π) only: the disk's area element
        // is uniform in φ and the clamped bilinear filter integrates to the texels' mean, so Φ = π A s mean.
        const int w = 32;
        Image img(w, 4);
        double mean[3] = {};
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < w; ++x) {
                float v = 1 + 0.8f * std::sin(2 * kPi * (x + 0.5f) / w);
                img(x, y) = Color3(v, 0.5f * v, 2 - v);
                for (int c = 0; c < 3; ++c) mean[c] += img(x, y)[c] / (4.0 * w);
            }
        DiskShape disk(Transform::translate({0, 0, 1}), 0, 0.5f, 0, false);
        DiffuseAreaLight light(&disk, std::make_shared<const Image>(img), 2.0f, false);
        double k = kPiD * kPiD * 0.25 * 2;
        const std::string name = "image area light (disk r = 0.5, image along φ, scale 2)";
        Color3 phi(float(k * mean[0]), float(k * mean[1]), float(k * mean[2]));
        out.push_back(check_light_power(light, name, "Φ = π A s mean(L)", phi, photons, o));
        // power() integrates the image over the shape by quadrature (n² stratum centres of the disk's
        // concentric sampling, n = 52 here): 9·10⁻⁴ off at the default seed; 2·10⁻³ allowed.
        out.push_back(check_light_power_method(light, name, "Φ = π A s mean(L)", phi, o, 2e-3));
    }
    {
        // A uniform sky L through a 1.2 x 1.2 window: Φ = A L ∫ cos θ dω = π A L (the portal within the
        // scene's sphere). Photons whose line misses the portal carry nothing (3 in 4 here), so more are
        // drawn.
        auto s = light_scene("");
        const std::array<Point3f, 4> portal{Point3f{-0.6f, -0.6f, 0.5f}, Point3f{-0.6f, 0.6f, 0.5f},
                                            Point3f{0.6f, 0.6f, 0.5f}, Point3f{0.6f, -0.6f, 0.5f}};
        PortalEnvironmentLight light(EnvironmentMap(Image(16, 16, Color3(0.5f, 1, 2)), EnvLayout::Octahedral),
                                     Transform(), 1, portal);
        light.preprocess(s->accelerator.bounds());
        const std::string name = "portal light (uniform sky, 1.2 x 1.2 window)";
        Color3 phi = I * float(kPiD * 1.44);
        out.push_back(check_light_power(light, name, "Φ = π A L", phi, 5 * photons, o));
        out.push_back(check_light_power_method(light, name, "Φ = π A L", phi, o));
    }
    return out;
}

} // namespace illum

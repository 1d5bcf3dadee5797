// pbrt-v4's portal infinite light: the rectified parameterisation (round trip, Jacobian, projected solid
// angles), radiance only through the portal, sample_li against pdf_li and against uniform sampling of le(),
// power against photons and pdf_le, bad portals, and a room lit through a window rendering as with the plain
// environment light, with less noise.
#include <gtest/gtest.h>

#include "illum/light/image_environment_light.h"
#include "illum/light/light_factory.h"
#include "illum/light/portal_environment_light.h"
#include "illum/math/warp.h"
#include "illum/scene/pbrt/parser.h"
#include "image_lights_support.h"
#include "test_support.h"

namespace illum {
namespace {

// A window in the plane z = 1, facing +z (the environment's side): p0 -> p1 along +y, p0 -> p3 along +x.
const std::array<Point3f, 4> kPortal{Point3f{-0.4f, -0.3f, 1}, Point3f{-0.4f, 0.3f, 1},
                                     Point3f{0.4f, 0.3f, 1}, Point3f{0.4f, -0.3f, 1}};
const Bounds3f kRoom{{-1, -1, -1}, {1, 1, 1}};

// A latitude-longitude sky: brighter towards +z, with a warm spot.
EnvironmentMap sky() {
    const int w = 64, h = 32;
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float theta = kPi * (y + 0.5f) / h, phi = 2 * kPi * (x + 0.5f) / w;
            Vector3f d = spherical_direction(std::sin(theta), std::cos(theta), phi);
            float v = 0.3f + std::max(0.0f, d.z);
            Color3 c(0.6f * v, 0.8f * v, v);
            if (dot(d, normalize(Vector3f{0.3f, 0.2f, 1})) > 0.97f) c += Color3(20, 15, 8);
            img(x, y) = c;
        }
    return EnvironmentMap(img, EnvLayout::LatLong);
}

TEST(PortalLight, RectifiedParameterisation) {
    PortalEnvironmentLight light(sky(), Transform(), 1, kPortal);
    EXPECT_NEAR(light.frame().n.z, 1, 1e-6);
    PCG32 rng(3);
    for (int i = 0; i < 1000; ++i) {
        Point2f uv{rng.uniform_float() * 0.98f + 0.01f, rng.uniform_float() * 0.98f + 0.01f};
        float jac = 0, jac2 = 0;
        Vector3f w = light.world_from_image(uv, &jac);
        auto back = light.image_from_world(w, &jac2);
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->x, uv.x, 1e-5f);
        EXPECT_NEAR(back->y, uv.y, 1e-5f);
        EXPECT_NEAR(jac, jac2, 1e-3f * jac);
        // dω/duv against the cross product of finite differences.
        const float h = 1e-3f;
        Vector3f du = (light.world_from_image({uv.x + h, uv.y}, nullptr) -
                       light.world_from_image({uv.x - h, uv.y}, nullptr)) /
                      (2 * h);
        Vector3f dv = (light.world_from_image({uv.x, uv.y + h}, nullptr) -
                       light.world_from_image({uv.x, uv.y - h}, nullptr)) /
                      (2 * h);
        EXPECT_NEAR(length(cross(du, dv)), jac, 1e-2f * jac + 1e-3f);
    }
    EXPECT_FALSE(light.image_from_world({0, 0, -1}, nullptr)); // behind the portal's plane
    // Projected solid angles over the whole square sum to π (the hemisphere's); a texel's against quadrature.
    const int n = 40;
    double total = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            total += rectified_psa(-kPiD / 2 + kPiD * i / n, -kPiD / 2 + kPiD * (i + 1) / n,
                                   -kPiD / 2 + kPiD * j / n, -kPiD / 2 + kPiD * (j + 1) / n);
    EXPECT_NEAR(total, kPiD, 1e-9);
    double a0 = 0.2, a1 = 0.5, b0 = -0.9, b1 = -0.3, quad = 0;
    const int m = 400;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            double a = a0 + (a1 - a0) * (i + 0.5) / m, b = b0 + (b1 - b0) * (j + 0.5) / m;
            double x = std::tan(a), y = std::tan(b), r2 = 1 + x * x + y * y;
            // cos θ dω = dA / r⁴ on the plane z = 1, dA = sec² α sec² β dα dβ.
            quad += (1 + x * x) * (1 + y * y) / (r2 * r2) * (a1 - a0) * (b1 - b0) / (double(m) * m);
        }
    EXPECT_NEAR(rectified_psa(a0, a1, b0, b1), quad, 1e-6);
}

// Radiance arrives only along rays through the portal, and there it is the environment's.
TEST(PortalLight, RadianceOnlyThroughThePortal) {
    EnvironmentMap map = sky();
    PortalEnvironmentLight light(map, Transform(), 2, kPortal);
    ImageEnvironmentLight plain(map, Transform(), 2);
    auto lambda = SampledWavelengths::rgb_mode();
    const Point3f o{0.1f, -0.2f, -0.5f};
    PCG32 rng(7);
    int through = 0;
    for (int i = 0; i < 20000; ++i) {
        Vector3f w = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        Radiance3 l = light.le(Ray{o, w}, lambda);
        float t = (1 - o.z) / w.z;
        Point3f q = o + w * t;
        bool crosses = w.z > 0 && std::abs(q.x) < 0.4f && std::abs(q.y) < 0.3f;
        bool clearly_out = w.z <= 0 || std::abs(q.x) > 0.41f || std::abs(q.y) > 0.31f;
        if (crosses) {
            ++through;
            // The rectified texel's value is the environment's (bilinear) radiance at the texel's centre.
            auto uv = light.image_from_world(w, nullptr);
            ASSERT_TRUE(uv);
            const int n = light.rectified().width();
            Point2f centre{(std::min(int(uv->x * n), n - 1) + 0.5f) / n,
                           (std::min(int(uv->y * n), n - 1) + 0.5f) / n};
            Radiance3 p = plain.le(Ray{o, light.world_from_image(centre, nullptr)}, lambda);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[c], p[c], 1e-4f * p[c]);
        } else if (clearly_out) {
            EXPECT_TRUE(l.is_black());
        }
    }
    EXPECT_GT(through, 100);
    // From outside (the environment's side) nothing is seen.
    EXPECT_TRUE(light.le(Ray{Point3f{0, 0, 2}, Vector3f{0, 0, 1}}, lambda).is_black());
}

// sample_li: directions through the portal only, with pdf_li's density; its estimate of the irradiance at a
// point equals that of uniform sphere sampling of le().
TEST(PortalLight, SampleLiAgainstPdfLiAndUniformSampling) {
    for (Point3f p : {Point3f{0.3f, 0.1f, -0.8f}, Point3f{-0.6f, -0.4f, -1}, Point3f{-0.5f, -0.3f, -0.9f}}) {
        PortalEnvironmentLight light(sky(), Transform(), 1, kPortal);
        auto lambda = SampledWavelengths::rgb_mode();
        LightSampleContext ctx(p, {}, Normal3f{0, 0, 1});
        test::MeanAccumulator by_light, by_sphere;
        PCG32 rng(11);
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            Point2f u{rng.uniform_float(), rng.uniform_float()};
            auto s = light.sample_li(ctx, u, lambda);
            if (s) {
                EXPECT_NEAR(light.pdf_li(ctx, s->wi, nullptr).value, s->pdf.value, 2e-3f * s->pdf.value);
                EXPECT_FALSE(light.le(Ray{p, s->wi}, lambda).is_black());
                by_light.add(s->biradiance[2] * std::max(0.0f, s->wi.z));
            } else {
                by_light.add(0);
            }
            Vector3f w = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
            by_sphere.add(light.le(Ray{p, w}, lambda)[2] * std::max(0.0f, w.z) * 4 * kPiD);
        }
        EXPECT_NEAR(by_light.mean, by_sphere.mean,
                    4 * std::hypot(by_light.std_error(), by_sphere.std_error()));
        EXPECT_LT(by_light.std_error(), by_sphere.std_error() / 3)
            << "portal sampling should beat uniform sampling";
    }
}

TEST(PortalLight, PowerAgainstPhotons) {
    PortalEnvironmentLight light(sky(), Transform::rotate(-30, {1, 0, 0}), 1.5f, kPortal);
    light.preprocess(kRoom);
    test::expect_photons_match_power(light, 400000, 13, "portal");
    test::expect_pdf_le_matches(light, 4000, 17, "portal", 50);
    // Every photon that carries light starts within the portal and travels inwards.
    PCG32 rng(19);
    for (int i = 0; i < 2000; ++i) {
        auto s = light.sample_le({rng.uniform_float(), rng.uniform_float()},
                                 {rng.uniform_float(), rng.uniform_float()}, SampledWavelengths::rgb_mode());
        if (!s) continue;
        EXPECT_NEAR(s->ray.o.z, 1, 1e-4f);
        EXPECT_LE(std::abs(s->ray.o.x), 0.4001f);
        EXPECT_LE(std::abs(s->ray.o.y), 0.3001f);
        EXPECT_LT(s->ray.d.z, 0);
    }
}

TEST(PortalLight, BadPortalsArePositionedErrors) {
    auto expect_error = [](const std::string& portal, const std::string& what) {
        SceneDesc d = parse_pbrt_string(
            "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1] \"point3 portal\" " + portal, "<test>",
            ".");
        Diagnostics diag;
        try {
            make_light(d.lights.at(0), diag);
            ADD_FAILURE() << "no error for " << portal;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("<test>:2:"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    expect_error("[0 0 0  1 0 0  1 1 0]", "needs 4 points");
    expect_error("[0 0 0  0 1 0  1 1 0.5  1 0 0]", "not a planar rectangle");
    expect_error("[0 0 0  0 1 0  1.5 1 0  1 0 0]", "not a planar rectangle");
    // A good one: no warning, every parameter used.
    SceneDesc d = parse_pbrt_string("WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1] \"point3 "
                                    "portal\" [0 0 0  0 1 0  1 1 0  1 0 0]",
                                    "<test>", ".");
    Diagnostics diag;
    auto light = make_light(d.lights.at(0), diag);
    EXPECT_TRUE(dynamic_cast<const PortalEnvironmentLight*>(light.get()));
    EXPECT_TRUE(diag.warnings().empty());
    EXPECT_TRUE(d.lights.at(0).params.unused().empty());
}

// A closed room lit only through a window in its ceiling: the portal light renders the same image as the
// plain environment light (within noise), with less noise.
std::string room(const std::string& light) {
    return fmt::format(R"(
Integrator "path" "integer maxdepth" [3]
LookAt 0 -0.9 -0.2  0 0.5 -0.6  0 0 1
Camera "perspective" "float fov" [70]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
{}
Material "diffuse" "rgb reflectance" [0.7 0.7 0.7]
# floor, walls (inward facing), and the ceiling z = 1 around the window [-0.4, 0.4] x [-0.3, 0.3]
Shape "trianglemesh" "point3 P" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 -1 -1  -1 1 -1  -1 1 1  -1 -1 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [1 -1 -1  1 1 -1  1 1 1  1 -1 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 -1 -1  1 -1 -1  1 -1 1  -1 -1 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 1 -1  1 1 -1  1 1 1  -1 1 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 -1 1  1 -1 1  1 -0.3 1  -1 -0.3 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 0.3 1  1 0.3 1  1 1 1  -1 1 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-1 -0.3 1  -0.4 -0.3 1  -0.4 0.3 1  -1 0.3 1] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [0.4 -0.3 1  1 -0.3 1  1 0.3 1  0.4 0.3 1] "integer indices" [0 1 2 0 2 3]
)",
                       light);
}

TEST(PortalLight, RoomThroughAWindowMatchesThePlainEnvironment) {
    std::string path = test::temp_image(sky().image(), "portal_sky");
    std::string plain = fmt::format(R"(LightSource "infinite" "string filename" "{}")", path);
    std::string portal = plain + R"( "point3 portal" [-0.4 -0.3 1  -0.4 0.3 1  0.4 0.3 1  0.4 -0.3 1])";
    for (const char* integrator : {"path", "bdpt"}) {
        test::RenderSetup s;
        s.integrator = integrator;
        s.spp = 32;
        s.seed = 1;
        Image p1 = test::render_pbrt(room(portal), s).image, e1 = test::render_pbrt(room(plain), s).image;
        s.seed = 2;
        Image p2 = test::render_pbrt(room(portal), s).image, e2 = test::render_pbrt(room(plain), s).image;
        // Noise: the mean squared difference of two independent renders is twice a render's variance.
        auto noise = [](const Image& a, const Image& b) {
            double sum = 0;
            for (std::size_t i = 0; i < a.pixel_count(); ++i) {
                double d = a.data()[i].average() - b.data()[i].average();
                sum += d * d;
            }
            return sum / (2.0 * a.pixel_count());
        };
        double var_portal = noise(p1, p2), var_plain = noise(e1, e2);
        for (int c = 0; c < 3; ++c) {
            auto mp = test::pixel_mean(p1, c), me = test::pixel_mean(e1, c);
            auto mp2 = test::pixel_mean(p2, c), me2 = test::pixel_mean(e2, c);
            double portal_mean = (mp.mean + mp2.mean) / 2, plain_mean = (me.mean + me2.mean) / 2;
            double se = std::sqrt((var_portal + var_plain) / (2.0 * p1.pixel_count()));
            EXPECT_GT(plain_mean, 0);
            EXPECT_NEAR(portal_mean, plain_mean, 4 * se + 2e-3 * plain_mean)
                << integrator << " channel " << c;
        }
        EXPECT_LT(var_portal, var_plain) << integrator;
        std::printf("%s: per-pixel variance portal %.3g, plain %.3g (ratio %.2f)\n", integrator, var_portal,
                    var_plain, var_plain / var_portal);
    }
    std::filesystem::remove(path);
}

} // namespace
} // namespace illum

// Light samplers for next-event estimation (direct_light_sampler.h): the bounds they rely on are
// conservative (a light is never given zero importance where it can reach the receiver), the BVH's and the
// exhaustive sampler's pmf() is the probability with which sample() picks each light, and renders with
// every sampler agree within noise.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include <fmt/format.h>

#include "illum/light/diffuse_area_light.h"
#include "illum/light/direct_light_sampler.h"
#include "illum/math/direction_cone.h"
#include "illum/math/frame.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "test_support.h"

namespace illum {
namespace {

// A floor under many emitters of every bounded kind: small quads (two triangles each, some facing up,
// away from the floor, some two-sided), a disk, a sphere, a rectangle patch, a point and a spot light,
// and (when `environment`) a dim uniform environment. `sampler`: the integrator's "lightsampler".
std::string many_lights_scene(const std::string& sampler, const std::string& integrator = "path",
                              bool environment = true, bool fog = false) {
    // The fog: around the camera and everything else, inside a sphere of interface material.
    const char* fog_medium = R"(MakeNamedMedium "fog" "string type" "homogeneous"
    "rgb sigma_a" [0.02 0.02 0.02] "rgb sigma_s" [0.08 0.08 0.08]
MediumInterface "" "fog"
)";
    const char* fog_boundary = R"(AttributeBegin
  MediumInterface "fog" ""
  Material "interface"
  Shape "sphere" "float radius" [30]
AttributeEnd
)";
    std::string s = fmt::format(R"(
Film "rgb" "integer xresolution" [20] "integer yresolution" [20] "string filename" "unused.exr"
LookAt 0 7 7  0 0 0  0 1 0
Integrator "{}" "string lightsampler" "{}" "integer maxdepth" [3]
{}Camera "perspective" "float fov" [55]
WorldBegin
{}Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-6 0 -6  6 0 -6  6 0 6  -6 0 6] "integer indices" [0 1 2 0 2 3]
Material "diffuse" "rgb reflectance" [0.3 0.5 0.3]
Shape "trianglemesh" "point3 P" [-1 0 -1  1 0 -1  1 2 -1  -1 2 -1] "integer indices" [0 1 2 0 2 3]
)",
                                integrator, sampler, fog ? fog_medium : "", fog ? fog_boundary : "");
    PCG32 rng(11);
    for (int i = 0; i < 14; ++i) {
        float x = -5 + 10 * rng.uniform_float(), z = -5 + 10 * rng.uniform_float();
        float y = 0.5f + 3 * rng.uniform_float(), h = 0.1f + 0.3f * rng.uniform_float();
        // Winding decides the emitting side (pbrt-v4: the side of the triangle's normal); alternate it.
        std::string idx = i % 3 == 0 ? "0 2 1 0 3 2" : "0 1 2 0 2 3";
        float r = rng.uniform_float(), g = rng.uniform_float(), b = rng.uniform_float();
        s += fmt::format(R"(AttributeBegin
  AreaLightSource "diffuse" "rgb L" [{} {} {}] "bool twosided" {}
  Shape "trianglemesh" "point3 P" [{} {} {}  {} {} {}  {} {} {}  {} {} {}] "integer indices" [{}]
AttributeEnd
)",
                         4 * r, 4 * g, 4 * b, i % 5 == 0 ? "true" : "false", x - h, y, z - h, x + h, y, z - h,
                         x + h, y + 0.2f * h, z + h, x - h, y + 0.2f * h, z + h, idx);
    }
    s += R"(AttributeBegin
  AreaLightSource "diffuse" "rgb L" [3 3 2]
  Translate 2 3 2
  Rotate 120 1 0 0
  Shape "disk" "float radius" [0.4]
AttributeEnd
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 2 3]
  Translate -2 1.5 2
  Shape "sphere" "float radius" [0.2]
AttributeEnd
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [2 2 2]
  Shape "bilinearmesh" "point3 P" [3 2.5 -3  4 2.5 -3  3 2.5 -2  4 2.5 -2] "integer indices" [0 1 2 3]
AttributeEnd
LightSource "point" "point3 from" [0 3 3] "rgb I" [2 2 2]
LightSource "spot" "point3 from" [-3 4 -3] "point3 to" [-3 0 -3] "float coneangle" [25]
    "float conedelta" [5] "rgb I" [20 20 20]
)";
    if (environment) s += "LightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\n";
    return s;
}

std::unique_ptr<Scene> build(const std::string& text) {
    return build_scene(parse_pbrt_string(text, "<test>", "."));
}

// A receiver: a point around the lights, with a unit normal or (one in four) none, as in a medium.
LightSampleContext random_receiver(PCG32& rng) {
    Point3f p{-6 + 12 * rng.uniform_float(), 4.5f * rng.uniform_float(), -6 + 12 * rng.uniform_float()};
    Normal3f n{};
    if (rng.uniform_uint32() % 4 != 0)
        n = Normal3f(sample_uniform_sphere(Point2f{rng.uniform_float(), rng.uniform_float()}));
    return LightSampleContext(p, {}, n);
}

TEST(DirectionCone, UnionHoldsBothCones) {
    PCG32 rng(3);
    for (int trial = 0; trial < 2000; ++trial) {
        auto random_cone = [&] {
            Vector3f w = sample_uniform_sphere(Point2f{rng.uniform_float(), rng.uniform_float()});
            // Narrow cones, wide ones, single directions and (rarely) the whole sphere.
            float c = trial % 7 == 0 ? 1.0f : (trial % 53 == 0 ? -1.0f : 1 - 2 * rng.uniform_float());
            return DirectionCone(w, c);
        };
        DirectionCone a = random_cone(), b = random_cone();
        if (trial % 11 == 0) b = DirectionCone(-a.w, b.cos_theta); // opposite axes
        DirectionCone u = union_of(a, b);
        for (const DirectionCone* c : {&a, &b}) {
            Frame f = Frame::from_z(c->w);
            for (int i = 0; i < 16; ++i) {
                // Directions on the cone's rim are the hardest to hold.
                Vector3f d = f.to_world(
                    sample_uniform_cone(Point2f{rng.uniform_float(), rng.uniform_float()}, c->cos_theta));
                if (i == 0)
                    d = f.to_world(Vector3f(safe_sqrt(1 - c->cos_theta * c->cos_theta), 0, c->cos_theta));
                ASSERT_GE(dot(u.w, normalize(d)), u.cos_theta - 1e-4f)
                    << "trial " << trial << ": a (" << a.cos_theta << "), b (" << b.cos_theta << ")";
            }
        }
    }
}

TEST(LightBounds, NormalConesHoldEverySurfaceNormal) {
    auto scene = build(many_lights_scene("bvh"));
    PCG32 rng(5);
    int area_lights = 0;
    for (const auto& l : scene->lights) {
        const auto* area = dynamic_cast<const DiffuseAreaLight*>(l.get());
        if (!area) continue;
        ++area_lights;
        DirectionCone cone = area->shape()->normal_bounds();
        std::optional<LightBounds> b = area->bounds();
        ASSERT_TRUE(b.has_value());
        for (int i = 0; i < 64; ++i) {
            AreaShapeSample s = area->shape()->sample_area(Point2f{rng.uniform_float(), rng.uniform_float()});
            ASSERT_GE(dot(cone.w, normalize(Vector3f(s.n))), cone.cos_theta - 1e-4f) << "light " << l->index;
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(s.p[k], b->bounds.lo[k] - 1e-4f);
                ASSERT_LE(s.p[k], b->bounds.hi[k] + 1e-4f);
            }
        }
    }
    EXPECT_EQ(area_lights, 2 * 14 + 3);
}

// Where a light's bounds give zero importance, or the sampler zero probability, the light delivers
// nothing: every sample_li there is empty or black (the bounds are conservative, so sampling by them is
// unbiased). Half the receivers are taken close to a light, where the box's extent matters most.
TEST(LightBounds, ZeroImportanceOnlyWhereTheLightDeliversNothing) {
    for (const char* kind : {"bvh", "exhaustive"}) {
        auto scene = build(many_lights_scene(kind));
        PCG32 rng(9);
        int zeros = 0;
        for (const auto& l : scene->lights) {
            std::optional<LightBounds> b = l->bounds();
            if (!b) continue;
            Point3f c = b->bounds.center();
            float r = std::max(length(b->bounds.diagonal()), 0.2f);
            for (int trial = 0; trial < 1000; ++trial) {
                LightSampleContext ctx = random_receiver(rng);
                if (trial % 2 == 0) {
                    Vector3f d = sample_uniform_sphere(Point2f{rng.uniform_float(), rng.uniform_float()});
                    ctx.p = c + d * (r * std::cbrt(rng.uniform_float()));
                }
                float importance = b->importance(ctx.p, ctx.n);
                ASSERT_TRUE(std::isfinite(importance) && importance >= 0);
                float pmf = scene->direct_light_sampler.pmf(ctx, l.get());
                if (importance > 0 && pmf > 0) continue;
                ++zeros;
                for (int i = 0; i < 32; ++i) {
                    auto ls = l->sample_li(ctx, Point2f{rng.uniform_float(), rng.uniform_float()},
                                           SampledWavelengths::rgb_mode());
                    if (!ls) continue;
                    bool black = ls->biradiance.s.is_black();
                    // A receiver with a normal takes nothing from exactly along its tangent plane either.
                    if (!black && ctx.n != Normal3f{}) black = dot(ctx.n, ls->wi) == 0;
                    ASSERT_TRUE(black)
                        << kind << ": light " << l->index << " at (" << ctx.p.x << ", " << ctx.p.y << ", "
                        << ctx.p.z << "), importance " << importance << ", pmf " << pmf;
                }
            }
        }
        EXPECT_GT(zeros, 1000) << kind; // the one-sided and spot lights turn away from many receivers
    }
}

// importance_pair (the light BVH's two children in SSE lanes) gives importance()'s values bit for bit:
// the scene's lights and the BVH's unions of them, and random bounds (one- and two-sided, points, wide and
// narrow cones, receivers inside and outside the boxes, with and without a normal), two at a time.
TEST(LightBounds, ImportancePairIsImportanceBitForBit) {
    std::vector<PreparedLightBounds> bounds;
    auto scene = build(many_lights_scene("bvh"));
    std::optional<LightBounds> all;
    for (const auto& l : scene->lights)
        if (std::optional<LightBounds> b = l->bounds()) {
            bounds.emplace_back(*b);
            all = all ? union_of(*all, *b) : *b;
        }
    bounds.emplace_back(*all);
    PCG32 rng(23);
    auto u = [&] { return rng.uniform_float(); };
    for (int i = 0; i < 200; ++i) {
        LightBounds b;
        Point3f c{4 * u() - 2, 4 * u() - 2, 4 * u() - 2};
        b.bounds.extend(c);
        if (i % 5 != 0) b.bounds.extend(c + Vector3f{u(), u() * u(), 0.5f * u()}); // else a point
        b.w = sample_uniform_sphere({u(), u()});
        b.phi = 10 * u();
        b.cos_theta_o = i % 3 == 0 ? -1 : 2 * u() - 1;
        b.cos_theta_e = i % 4 == 0 ? 0 : u();
        b.two_sided = i % 2 == 0;
        bounds.emplace_back(b);
    }
    int compared = 0, nonzero = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const PreparedLightBounds& a = bounds[rng.uniform_uint32() % bounds.size()];
        const PreparedLightBounds& b = bounds[rng.uniform_uint32() % bounds.size()];
        LightSampleContext ctx = random_receiver(rng);
        if (trial % 3 == 0) ctx.p = a.centre + Vector3f{u() - 0.5f, u() - 0.5f, u() - 0.5f} * (0.1f * u());
        if (trial % 7 == 0) ctx.p = b.centre;
        if (trial % 2 == 0) ctx.n = Normal3f{};
        float pa = -1, pb = -1;
        importance_pair(a, b, ctx.p, ctx.n, &pa, &pb);
        const float ea = a.importance(ctx.p, ctx.n), eb = b.importance(ctx.p, ctx.n);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(pa), std::bit_cast<std::uint32_t>(ea)) << "trial " << trial;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(pb), std::bit_cast<std::uint32_t>(eb)) << "trial " << trial;
        compared += 2;
        nonzero += (ea > 0) + (eb > 0);
    }
    EXPECT_EQ(compared, 8000);
    EXPECT_GT(nonzero, 2000); // not only the zeros of turned-away lights
    EXPECT_LT(nonzero, 7900); // nor only lit receivers
}

// pmf() sums to one over the lights (less what the BVH loses, below), agrees with the probability sample()
// returns, and is the measure of the u that pick each light: with N evenly spaced u, each light is picked
// pmf · N times up to one.
void expect_consistent_sampler(LightSamplerKind kind) {
    auto scene = build(many_lights_scene(light_sampler_name(kind)));
    const DirectLightSampler& sampler = scene->direct_light_sampler;
    ASSERT_EQ(sampler.kind(), kind);
    PCG32 rng(17);
    const int n = 4096;
    for (int trial = 0; trial < 60; ++trial) {
        LightSampleContext ctx = random_receiver(rng);
        std::vector<double> pmf(scene->lights.size());
        double sum = 0;
        for (const auto& l : scene->lights) sum += pmf[l->index] = sampler.pmf(ctx, l.get());
        std::vector<int> count(scene->lights.size(), 0);
        int none = 0;
        for (int i = 0; i < n; ++i) {
            float p = 0;
            const Light* l = sampler.sample(ctx, (float(i) + 0.5f) / float(n), &p);
            if (!l) {
                ++none;
                continue;
            }
            ++count[l->index];
            ASSERT_NEAR(p, pmf[l->index], 1e-5 + 1e-4 * pmf[l->index]) << "light " << l->index;
        }
        // The BVH may walk into a node that reaches the receiver whose children both do not (the union's
        // bounds are looser than its parts'): that u picks nothing, and the pmfs sum to one less its measure.
        EXPECT_LE(sum, 1 + 1e-4);
        EXPECT_NEAR(sum + double(none) / n, 1, 2.0 / n + 1e-4);
        if (kind != LightSamplerKind::bvh && none < n) {
            EXPECT_NEAR(sum, 1, 1e-4);
        }
        for (std::size_t i = 0; i < count.size(); ++i)
            EXPECT_NEAR(count[i], pmf[i] * n, 1.5 + 1e-3 * n) << "light " << i << " of trial " << trial;
    }
}

TEST(LightSampler, BvhPmfIsItsSamplingProbability) { expect_consistent_sampler(LightSamplerKind::bvh); }
TEST(LightSampler, ExhaustivePmfIsItsSamplingProbability) {
    expect_consistent_sampler(LightSamplerKind::exhaustive);
}
TEST(LightSampler, UniformAndPowerPmfAreTheirSamplingProbability) {
    expect_consistent_sampler(LightSamplerKind::uniform);
    expect_consistent_sampler(LightSamplerKind::power);
}

TEST(LightSampler, BvhPrefersTheNearbyFacingLights) {
    auto scene = build(many_lights_scene("bvh", "path", false));
    const BvhLightSampler& bvh = scene->direct_light_sampler.bvh();
    EXPECT_EQ(bvh.node_count(), 2 * scene->lights.size() - 1);
    EXPECT_LE(bvh.depth(), 12);
    // Just under the spot light, on the floor: the spot outweighs every other light.
    LightSampleContext under_spot(Point3f{-3, 0, -3}, {}, Normal3f{0, 1, 0});
    const Light* best = nullptr;
    float best_pmf = 0;
    for (const auto& l : scene->lights) {
        float p = scene->direct_light_sampler.pmf(under_spot, l.get());
        if (p > best_pmf) best_pmf = p, best = l.get();
    }
    ASSERT_NE(best, nullptr);
    EXPECT_TRUE(best->position().has_value() && best->type() == LightType::DeltaPosition);
    EXPECT_GT(best_pmf, 0.3f);
}

TEST(LightSampler, UnknownNameIsAnErrorAtItsPosition) {
    try {
        build(many_lights_scene("nearest"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.where().line, 4);
        EXPECT_NE(std::string(e.what()).find("light sampler \"nearest\""), std::string::npos) << e.what();
    }
}

// Renders with the BVH, exhaustive or uniform sampler against renders by power: each pair of independent
// renders A, B (and A2, B2 of other seeds) estimates the squared bias per pixel as
//   (A - B)² - (A - A2)²/2 - (B - B2)²/2,
// zero on average when both are unbiased; its mean over the pixels must be within 4 standard errors.
void expect_same_image_as_power(const std::string& kind, const std::string& integrator, bool fog = false,
                                int spp = 48) {
    auto render_with = [&](const std::string& sampler, std::uint64_t seed) {
        return test::render_pbrt(many_lights_scene(sampler, integrator, true, fog),
                                 test::independent_setup(integrator, spp, false, -2, seed))
            .image;
    };
    Image a = render_with(kind, 1), a2 = render_with(kind, 2), b = render_with("power", 3),
          b2 = render_with("power", 4);
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, diff = 0, diff2 = 0, mean_a = 0;
        std::size_t n = a.pixel_count();
        for (std::size_t i = 0; i < n; ++i) {
            double A = a.data()[i][c], A2 = a2.data()[i][c], B = b.data()[i][c], B2 = b2.data()[i][c];
            double d = (A - B) * (A - B) - 0.5 * (A - A2) * (A - A2) - 0.5 * (B - B2) * (B - B2);
            sum += d, sum2 += d * d, diff += A - B, diff2 += (A - B) * (A - B), mean_a += A;
        }
        double mean = sum / double(n), se = std::sqrt((sum2 / double(n) - mean * mean) / double(n - 1));
        EXPECT_LT(std::abs(mean), 4 * se + 1e-12) << kind << " " << integrator << " channel " << c;
        // And the images' means: the mean of A - B over the (independent) pixels, within 4 standard errors.
        double mean_d = diff / double(n);
        double se_d = std::sqrt((diff2 / double(n) - mean_d * mean_d) / double(n - 1));
        EXPECT_LT(std::abs(mean_d), 4 * se_d)
            << kind << " " << integrator << " channel " << c << ": image mean " << mean_a / double(n)
            << ", difference " << mean_d;
    }
}

TEST(LightSampler, BvhRendersAsPowerDoes) { expect_same_image_as_power("bvh", "path"); }
TEST(LightSampler, ExhaustiveAndUniformRenderAsPowerDoes) {
    expect_same_image_as_power("exhaustive", "path");
    expect_same_image_as_power("uniform", "path");
}
// volpath picks by the light sampler at surfaces and by power in a medium; both meet at the MIS weights.
TEST(LightSampler, BvhRendersAsPowerDoesInFog) { expect_same_image_as_power("bvh", "volpath", true, 512); }

} // namespace
} // namespace illum

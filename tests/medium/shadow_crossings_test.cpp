// Shadow rays through stacks of media (render/shadow_transmittance.h): one occlusion traversal gathers the
// interface crossings (Accelerator::shadow_crossings) and the stretches between them take the media the
// interfaces separate; a ray crossing more surfaces than fit is traced crossing by crossing. Both ways must
// give exp(-Σ σ_t,i d_i) exactly (homogeneous media), and any opaque surface on the way must block the ray.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "illum/render/shadow_transmittance.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {
namespace {

// n slabs of thickness 0.1 between z = -k/10 planes, k = 0..n: slab i (between z = -i/10 and -(i+1)/10)
// holds medium "m<i>" of σ_a = 0.5 (i + 1); each plane is an interface between its two neighbours, so a
// ray down -z from z = 1 to z = -(n + 1)/10 crosses n + 1 surfaces. `blocker`: an opaque square in slab 0.
std::unique_ptr<Scene> slab_stack(int n, bool blocker, bool patches = false) {
    std::string text = "Camera \"perspective\"\nWorldBegin\n";
    for (int i = 0; i < n; ++i)
        text +=
            fmt::format("MakeNamedMedium \"m{}\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [{} {} {}] "
                        "\"rgb sigma_s\" [0 0 0]\n",
                        i, 0.5 * (i + 1), 0.5 * (i + 1), 0.5 * (i + 1));
    text += "Material \"interface\"\n";
    for (int k = 0; k <= n; ++k) {
        // Normal +z: "outside" is above the plane (slab k-1, or none for k = 0), "inside" below (slab k).
        std::string inside = k < n ? fmt::format("m{}", k) : "";
        std::string outside = k > 0 ? fmt::format("m{}", k - 1) : "";
        double z = -0.1 * k;
        // (The same plane as a bilinear patch, corners p00 p10 p01 p11, for the patches' occlusion callback.)
        std::string shape =
            patches ? "Shape \"bilinearmesh\" \"point3 P\" [-5 -5 {z} 5 -5 {z} -5 5 {z} 5 5 {z}] "
                      "\"integer indices\" [0 1 2 3] \"normal N\" [0 0 1 0 0 1 0 0 1 0 0 1]\n"
                    : "Shape \"trianglemesh\" \"point3 P\" [-5 -5 {z} 5 -5 {z} 5 5 {z} -5 5 {z}] "
                      "\"integer indices\" [0 1 2 0 2 3] \"normal N\" [0 0 1 0 0 1 0 0 1 0 0 1]\n";
        text += fmt::format("AttributeBegin\nMediumInterface \"{}\" \"{}\"\n", inside, outside) +
                fmt::format(fmt::runtime(shape), fmt::arg("z", z)) + "AttributeEnd\n";
    }
    if (blocker)
        text += "Material \"diffuse\"\nShape \"trianglemesh\" \"point3 P\" [-1 -1 -0.05 1 -1 -0.05 1 1 -0.05 "
                "-1 1 -0.05] \"integer indices\" [0 1 2 0 2 3]\n";
    return build_scene(parse_pbrt_string(text, "<test>", "."));
}

SampledSpectrum transmittance_down(const Scene& scene, int n, std::uint64_t* rays) {
    Point3f from(0.1f, 0.2f, 1), to(0.1f, 0.2f, float(-0.1 * n - 0.05));
    Ray ray{from, to - from, 1 - 1e-4f};
    ShadowTarget target{to, {}, {}, false, normalize(to - from)};
    PCG32 rng(3);
    SampledSpectrum r_u(1.0f), r_l(1.0f);
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    return shadow_transmittance(scene, ray, target, 0, rng, rgb, &r_u, &r_l, rays);
}

TEST(ShadowCrossings, StackedMediaGiveTheProductOfTheirTransmittances) {
    // 3 slabs: 4 crossings, gathered in one traversal. 12 slabs: 13 crossings, more than fit
    // (kMaxShadowCrossings), so the ray is traced crossing by crossing: one ray per crossing plus one.
    for (int n : {3, 12}) {
        auto scene = slab_stack(n, false);
        double optical_depth = 0;
        for (int i = 0; i < n; ++i) optical_depth += 0.5 * (i + 1) * 0.1;
        // The last stretch, below the last plane to the target, is in vacuum.
        std::uint64_t rays = 0;
        SampledSpectrum t = transmittance_down(*scene, n, &rays);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], std::exp(-optical_depth), 2e-5) << n << " slabs";
        if (n + 1 <= Accelerator::kMaxShadowCrossings)
            EXPECT_EQ(rays, 1u) << "one traversal for " << n + 1 << " crossings";
        else
            EXPECT_EQ(rays, std::uint64_t(1 + n + 2)) << "crossing by crossing after the gathering traversal";
    }
}

TEST(ShadowCrossings, BilinearPatchInterfacesLetTheRayThrough) {
    // The same stack of 3 slabs with bilinear patches (Embree user geometry) as the interfaces.
    auto scene = slab_stack(3, false, true);
    std::uint64_t rays = 0;
    SampledSpectrum t = transmittance_down(*scene, 3, &rays);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t[c], std::exp(-0.1 * 0.5 * (1 + 2 + 3)), 2e-5);
    EXPECT_EQ(rays, 1u);
    EXPECT_TRUE(transmittance_down(*slab_stack(3, true, true), 3, &rays).is_black());
}

TEST(ShadowCrossings, AnOpaqueSurfaceAmongInterfacesBlocks) {
    for (int n : {3, 12}) {
        auto scene = slab_stack(n, true);
        std::uint64_t rays = 0;
        EXPECT_TRUE(transmittance_down(*scene, n, &rays).is_black()) << n << " slabs";
    }
}

} // namespace
} // namespace illum

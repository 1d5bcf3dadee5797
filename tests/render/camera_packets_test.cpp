// Camera rays in Embree packets (Accelerator::find_packet, the render loop's batches): a packet finds
// exactly what the rays find one by one; scenes with callbacks that take single rays only do not use
// packets; and the render loop gives the same image, bit for bit, with and without them, for every
// integrator that takes the packet's hits, both resumable samplers, whole and partial packets, a
// texture-filtered scene (each sample's ray differentials) and a moving camera (each ray's time).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/render/integrator.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {
namespace {

// A box of triangles open towards the camera, an instanced object inside and one sphere (tested directly,
// outside Embree).
const char* kBox = R"(
LookAt 0 0 -2.5  0 0 0  0 1 0
Camera "perspective" "float fov" 50
Film "rgb" "integer xresolution" 20 "integer yresolution" 12
WorldBegin
LightSource "point" "rgb I" [3 3 3] "point3 from" [0 0.5 -0.5]
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "trianglemesh" "integer indices" [4 6 5 4 7 6  0 4 5 0 5 1  3 2 6 3 6 7  1 5 6 1 6 2]
    "point3 P" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1]
ObjectBegin "wedge"
Shape "trianglemesh" "integer indices" [0 1 2  0 2 3  0 3 1] "point3 P" [0 0 0  0.3 0 0  0 0.3 0  0 0 0.3]
ObjectEnd
AttributeBegin
Translate -0.5 -0.6 0.2
ObjectInstance "wedge"
AttributeEnd
AttributeBegin
Translate 0.4 0.3 0.3
Rotate 30 1 1 0
ObjectInstance "wedge"
AttributeEnd
AttributeBegin
Translate 0.3 -0.5 0.4
Shape "sphere" "float radius" 0.3
AttributeEnd
)";

std::unique_ptr<Scene> build(const std::string& text, const std::string& dir = ".") {
    return build_scene(parse_pbrt_string(text, "<test>", dir));
}

void expect_same(const Accelerator::Found& a, const Accelerator::Found& b) {
    const RTCRayHit &x = a.rh, &y = b.rh;
    EXPECT_EQ(std::memcmp(&x.ray.tfar, &y.ray.tfar, sizeof(float)), 0);
    EXPECT_EQ(x.ray.time, y.ray.time);
    EXPECT_EQ(x.hit.geomID, y.hit.geomID);
    EXPECT_EQ(x.hit.instID[0], y.hit.instID[0]);
    if (x.hit.geomID == RTC_INVALID_GEOMETRY_ID) return;
    EXPECT_EQ(x.hit.primID, y.hit.primID);
    EXPECT_EQ(x.hit.u, y.hit.u);
    EXPECT_EQ(x.hit.v, y.hit.v);
    EXPECT_EQ(x.hit.Ng_x, y.hit.Ng_x);
    EXPECT_EQ(x.hit.Ng_y, y.hit.Ng_y);
    EXPECT_EQ(x.hit.Ng_z, y.hit.Ng_z);
}

TEST(CameraPackets, APacketFindsWhatEachRayFindsAlone) {
    auto scene = build(kBox);
    const Accelerator& acc = scene->accelerator;
    ASSERT_TRUE(acc.packets_supported());
    PCG32 rng;
    int hits = 0, instance_hits = 0, sphere_hits = 0;
    for (int round = 0; round < 400; ++round) {
        const int n = 1 + round % Accelerator::kPacket;
        Ray rays[Accelerator::kPacket];
        for (int i = 0; i < n; ++i) {
            // Coherent rays (a pencil from near the camera) in even rounds, incoherent ones in odd rounds.
            Point3f o = round % 2 ? Point3f{rng.uniform_float() - 0.5f, rng.uniform_float() - 0.5f,
                                            rng.uniform_float() - 0.5f}
                                  : Point3f{0, 0, -0.9f};
            Vector3f d =
                round % 2 ? sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()})
                          : normalize(Vector3f{rng.uniform_float() - 0.5f, rng.uniform_float() - 0.5f, 1.0f});
            rays[i] = Ray{o, d, i == 2 ? 0.7f : kInfinity};
        }
        // An untraceable ray (a NaN direction) finds nothing either way.
        if (round % 7 == 3) rays[n - 1].d.x = std::numeric_limits<float>::quiet_NaN();
        Accelerator::Found packet[Accelerator::kPacket];
        const std::uint32_t bits = acc.find_packet(rays, n, packet);
        EXPECT_EQ(bits >> n, 0u);
        for (int i = 0; i < n; ++i) {
            Accelerator::Found alone;
            const bool found = acc.find(rays[i], &alone);
            EXPECT_EQ(found, bool((bits >> i) & 1u)) << "round " << round << " ray " << i;
            if (!found) continue;
            expect_same(packet[i], alone);
            ++hits;
            if (alone.rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) ++instance_hits;
            if (acc.shape(alone.rh.hit.geomID)) ++sphere_hits;
            // And the surface the two complete to.
            SurfaceHit a, b;
            ASSERT_TRUE(acc.complete(packet[i], rays[i], &a));
            ASSERT_TRUE(acc.complete(alone, rays[i], &b));
            EXPECT_EQ(a.p, b.p);
            EXPECT_EQ(a.n, b.n);
        }
    }
    // Every kind of geometry was met.
    EXPECT_GT(hits, 1000);
    EXPECT_GT(instance_hits, 10);
    EXPECT_GT(sphere_hits, 10);
}

TEST(CameraPackets, ScenesWithSingleRayCallbacksDoNotUsePackets) {
    const std::string head = R"(
Camera "perspective"
Film "rgb" "integer xresolution" 4 "integer yresolution" 4
WorldBegin
)";
    const std::string quad =
        R"(Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 -1 1  1 -1 1  1 1 1  -1 1 1])";
    EXPECT_TRUE(build(head + quad)->accelerator.packets_supported());
    // Two analytic shapes are tested outside Embree; a third puts all three in Embree as user geometry.
    const std::string sphere = "Shape \"sphere\" \"float radius\" 0.1\n";
    EXPECT_TRUE(build(head + quad + "\n" + sphere + sphere)->accelerator.packets_supported());
    EXPECT_FALSE(build(head + quad + "\n" + sphere + sphere + sphere)->accelerator.packets_supported());
    // An alpha cut-out (Embree's filter callback).
    EXPECT_FALSE(build(head + R"(Shape "trianglemesh" "float alpha" 0.5 "integer indices" [0 1 2]
                                 "point3 P" [-1 -1 1  1 -1 1  1 1 1])")
                     ->accelerator.packets_supported());
    // Bilinear patches (user geometry), also inside an object instance.
    const std::string patch = R"(Shape "bilinearmesh" "point3 P" [-1 -1 1  1 -1 1  -1 1 1  1 1 1]
                                 "integer indices" [0 1 2 3])";
    EXPECT_FALSE(build(head + patch)->accelerator.packets_supported());
    EXPECT_FALSE(build(head + "ObjectBegin \"p\"\n" + patch + "\nObjectEnd\nObjectInstance \"p\"\n")
                     ->accelerator.packets_supported());
    // An analytic shape in an object instance is Embree's user geometry too.
    EXPECT_FALSE(build(head + "ObjectBegin \"s\"\n" + sphere + "ObjectEnd\nObjectInstance \"s\"\n")
                     ->accelerator.packets_supported());
}

struct Case {
    std::string integrator, sampler;
    int spp;
    bool spectral;
};

Image render_with(const Scene& scene, const Case& s, bool packets, int threads = 2) {
    auto integrator = make_integrator(s.integrator, scene, 5);
    RenderOptions o;
    o.spp = s.spp;
    o.sampler = s.sampler;
    o.spectral = s.spectral;
    o.threads = threads;
    o.quiet = true;
    o.camera_packets = packets;
    return render(scene, *integrator, o).image;
}

void expect_identical(const Image& a, const Image& b) {
    ASSERT_EQ(a.pixel_count(), b.pixel_count());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.pixel_count() * sizeof(a.data()[0])), 0);
}

TEST(CameraPackets, ImagesAreTheSameWithAndWithoutPackets) {
    auto scene = build(kBox);
    const Case setups[] = {
        {"path", "sobol", 5, false},        {"path", "independent", 5, true}, {"path", "sobol", 1, true},
        {"path", "independent", 8, false},  {"direct", "sobol", 3, false},    {"albedo", "sobol", 2, false},
        {"normal", "independent", 9, true},
    };
    for (const Case& s : setups) {
        SCOPED_TRACE(s.integrator + " " + s.sampler + " " + std::to_string(s.spp));
        Image with = render_with(*scene, s, true), without = render_with(*scene, s, false);
        expect_identical(with, without);
        double sum = 0;
        for (std::size_t i = 0; i < with.pixel_count(); ++i) sum += std::abs(with.data()[i].g);
        EXPECT_GT(sum, 0); // something was seen
    }
    // The thread count does not matter either.
    expect_identical(render_with(*scene, {"path", "sobol", 4, true}, true, 1),
                     render_with(*scene, {"path", "sobol", 4, true}, true, 2));
}

TEST(CameraPackets, MediaMotionAndTextureFilteringKeepTheirImages) {
    // volpath in a fog, with a camera that moves during the shutter (every ray its own time).
    std::string text = kBox;
    text.replace(text.find("LookAt"), 0,
                 "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.1 0.1] "
                 "\"rgb sigma_s\" [0.3 0.3 0.3]\nMediumInterface \"\" \"fog\"\n"
                 "ActiveTransform EndTime\nTranslate 0.05 0 0\nActiveTransform All\n");
    text.replace(text.find("WorldBegin"), 10, "WorldBegin\nMediumInterface \"fog\" \"fog\"");
    auto scene = build(text);
    ASSERT_TRUE(scene->has_motion);
    ASSERT_TRUE(scene->camera_medium);
    for (const Case& s : {Case{"volpath", "independent", 3, true}, Case{"path", "sobol", 9, false}}) {
        SCOPED_TRACE(s.integrator);
        expect_identical(render_with(*scene, s, true), render_with(*scene, s, false));
    }
    // Filtered textures: each sample's ray differentials go with it.
    const std::string dir = std::string(ILLUM_SOURCE_DIR) + "/scenes/texture-filtering";
    std::ifstream in(dir + "/texture-filtering.pbrt");
    std::stringstream ss;
    ss << in.rdbuf();
    auto textured = build(ss.str(), dir);
    ASSERT_TRUE(textured->texture_filtering);
    ASSERT_TRUE(textured->accelerator.packets_supported());
    expect_identical(render_with(*textured, {"path", "sobol", 3, false}, true),
                     render_with(*textured, {"path", "sobol", 3, false}, false));
}

} // namespace
} // namespace illum

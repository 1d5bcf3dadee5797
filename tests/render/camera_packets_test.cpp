// Camera rays in Embree packets (Accelerator::find_packet, the render loop's batches): a packet finds
// exactly what the rays find one by one, also where Embree calls illum's callbacks with the packet (analytic
// shapes and bilinear patches as user geometry, alpha cut-outs, in instances too), and scenes with curves
// (whose packet hits Embree rounds otherwise) do not use packets; and the render loop gives the same image,
// bit for bit, with and without packets, for every integrator that takes the packet's hits, every
// sampler, whole and partial packets, a texture-filtered scene (each sample's ray differentials) and a
// moving camera (each ray's time).
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

// The same box with geometry whose hits Embree's callbacks decide: three spheres (more than the two tested
// outside Embree), a disk and a cylinder, a bilinear patch, a mesh and a sphere with alpha cut-outs, and a
// sphere and a patch inside an object instance.
std::string with_callbacks() {
    std::string text = kBox;
    text += R"(
Shape "sphere" "float radius" 0.15
AttributeBegin
Translate -0.4 0.4 0.3
Shape "sphere" "float radius" 0.2 "float alpha" 0.5
Shape "disk" "float radius" 0.3
AttributeEnd
AttributeBegin
Translate 0.5 0.5 0.6
Rotate 70 1 0 0
Shape "cylinder" "float radius" 0.1 "float zmin" -0.2 "float zmax" 0.2
AttributeEnd
Shape "bilinearmesh" "point3 P" [-0.9 -0.9 0.9  0.2 -0.9 0.7  -0.9 0.2 0.8  0.2 0.2 0.5]
    "integer indices" [0 1 2 3]
Shape "trianglemesh" "float alpha" 0.4 "integer indices" [0 1 2  0 2 3]
    "point3 P" [-0.6 -0.6 0  0.6 -0.6 0  0.6 0.6 0  -0.6 0.6 0]
ObjectBegin "round"
Shape "sphere" "float radius" 0.1
Shape "bilinearmesh" "point3 P" [0 0 0  0.2 0 0  0 0.2 0.05  0.2 0.2 0] "integer indices" [0 1 2 3]
ObjectEnd
AttributeBegin
Translate 0.2 0.6 -0.2
ObjectInstance "round"
AttributeEnd
)";
    return text;
}

// find_packet against find for coherent pencils of rays (even rounds) and incoherent rays (odd rounds),
// with every packet size and an untraceable ray now and then. Returns the hits by kind of record.
struct HitCounts {
    int hits = 0, instance_hits = 0, shape_hits = 0;
};
HitCounts expect_packets_match(const Accelerator& acc, int rounds) {
    PCG32 rng;
    HitCounts counts;
    for (int round = 0; round < rounds; ++round) {
        const int n = 1 + round % Accelerator::kPacket;
        Ray rays[Accelerator::kPacket];
        const Vector3f axis =
            normalize(Vector3f{rng.uniform_float() - 0.5f, rng.uniform_float() - 0.5f, 1.0f});
        for (int i = 0; i < n; ++i) {
            Point3f o = round % 2 ? Point3f{rng.uniform_float() - 0.5f, rng.uniform_float() - 0.5f,
                                            rng.uniform_float() - 0.5f}
                                  : Point3f{0, 0, -0.9f};
            Vector3f d = round % 2 ? sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()})
                                   : normalize(axis + Vector3f{rng.uniform_float() - 0.5f,
                                                               rng.uniform_float() - 0.5f, 0.0f} *
                                                          0.05f);
            rays[i] = Ray{o, d, i == 2 ? 0.7f : kInfinity};
        }
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
            ++counts.hits;
            if (alone.rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID)
                ++counts.instance_hits;
            else if (acc.shape(alone.rh.hit.geomID))
                ++counts.shape_hits;
            // And the surfaces the two complete to.
            SurfaceHit a, b;
            EXPECT_TRUE(acc.complete(packet[i], rays[i], &a));
            EXPECT_TRUE(acc.complete(alone, rays[i], &b));
            EXPECT_EQ(a.p, b.p);
            EXPECT_EQ(a.n, b.n);
        }
    }
    return counts;
}

TEST(CameraPackets, APacketFindsWhatEachRayFindsAlone) {
    auto scene = build(kBox);
    HitCounts c = expect_packets_match(scene->accelerator, 400);
    // Every kind of geometry was met.
    EXPECT_GT(c.hits, 1000);
    EXPECT_GT(c.instance_hits, 10);
    EXPECT_GT(c.shape_hits, 10);
}

TEST(CameraPackets, CallbacksTakeAPacketRayByRay) {
    auto scene = build(with_callbacks());
    ASSERT_TRUE(scene->accelerator.packets_supported());
    HitCounts c = expect_packets_match(scene->accelerator, 2000);
    EXPECT_GT(c.hits, 5000);
    EXPECT_GT(c.instance_hits, 30);
    EXPECT_GT(c.shape_hits, 300);
}

struct Case {
    std::string integrator, sampler;
    int spp;
    bool spectral;
    bool adaptive = false; // a different number of samples in each pixel (render/adaptive_sampling.h)
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
    o.adaptive.enabled = s.adaptive;
    return render(scene, *integrator, o).image;
}

void expect_identical(const Image& a, const Image& b) {
    ASSERT_EQ(a.pixel_count(), b.pixel_count());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.pixel_count() * sizeof(a.data()[0])), 0);
}

TEST(CameraPackets, ScenesWithCurvesDoNotUsePackets) {
    const std::string curve = R"(Shape "curve" "point3 P" [-0.8 0 0.2  -0.3 0.5 0.2  0.3 -0.5 0.2  0.8 0 0.2]
                                    "float width" 0.08 "string type" "cylinder")";
    EXPECT_TRUE(build(kBox)->accelerator.packets_supported());
    EXPECT_FALSE(build(std::string(kBox) + curve)->accelerator.packets_supported());
    EXPECT_FALSE(
        build(std::string(kBox) + "ObjectBegin \"c\"\n" + curve + "\nObjectEnd\nObjectInstance \"c\"\n")
            ->accelerator.packets_supported());
}

TEST(CameraPackets, ImagesAreTheSameWithAndWithoutPackets) {
    auto scene = build(kBox);
    const Case setups[] = {
        {"path", "sobol", 5, false},
        {"path", "independent", 5, true},
        {"path", "sobol", 1, true},
        {"path", "independent", 8, false},
        {"direct", "sobol", 3, false},
        {"albedo", "sobol", 2, false},
        {"normal", "independent", 9, true},
        // Every other sampler (zsobol's cache of a pixel's digits must follow the resumed sample).
        {"path", "zsobol", 4, true},
        {"path", "zsobol", 16, false},
        {"path", "halton", 5, false},
        {"path", "pmj02bn", 4, true},
        {"path", "stratified", 6, false},
        {"path", "paddedsobol", 3, true},
        // Adaptive sampling: packets of a row's samples, pixel by pixel, whatever each pixel takes.
        {"path", "sobol", 32, false, true},
        {"path", "zsobol", 32, true, true},
    };
    for (const Case& s : setups) {
        SCOPED_TRACE(s.integrator + " " + s.sampler + " " + std::to_string(s.spp));
        Image with = render_with(*scene, s, true), without = render_with(*scene, s, false);
        expect_identical(with, without);
        double sum = 0;
        for (std::size_t i = 0; i < with.pixel_count(); ++i) sum += std::abs(with.data()[i].g);
        EXPECT_GT(sum, 0); // something was seen
    }
    // Callbacks that take the packets ray by ray, alpha cut-outs among them.
    auto callbacks = build(with_callbacks());
    for (const Case& s : {Case{"path", "sobol", 4, true}, Case{"albedo", "independent", 3, false}}) {
        SCOPED_TRACE(s.integrator + " with callbacks");
        expect_identical(render_with(*callbacks, s, true), render_with(*callbacks, s, false));
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
    expect_identical(render_with(*textured, {"path", "sobol", 3, false}, true),
                     render_with(*textured, {"path", "sobol", 3, false}, false));
}

} // namespace
} // namespace illum

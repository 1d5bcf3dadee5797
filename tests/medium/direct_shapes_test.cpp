// Two shortcuts of the accelerator for rays through media must give what the long way gives:
// - a world with at most Accelerator::kDirectShapes analytic shapes tests them outside Embree (commit()
//   disables their user geometry); hits, alpha cut-outs, occlusion and shadow crossings must be those of
//   the same shapes traversed by Embree (a world with more shapes);
// - Accelerator::medium_beyond (the side a ray leaves a surface to, from the geometric normal alone) must
//   name the medium complete() + SurfaceHit::medium_for name, for meshes, spheres (turned, scaled,
//   reversed), disks, cylinders and instanced meshes.
#include <gtest/gtest.h>

#include <string>

#include "illum/math/rng.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {
namespace {

std::unique_ptr<Scene> scene_of(const std::string& world) {
    return build_scene(parse_pbrt_string("Camera \"perspective\"\nWorldBegin\n" + world, "<test>", "."));
}

// A ray from a random point of the box [-2, 2]³ towards a random point near the origin.
Ray random_ray(PCG32& rng) {
    auto u = [&] { return rng.uniform_float(); };
    Point3f o(4 * u() - 2, 4 * u() - 2, 4 * u() - 2);
    Point3f to(u() - 0.5f, u() - 0.5f, u() - 0.5f);
    return Ray{o, to - o, kInfinity};
}

// The sphere under test, first in both worlds (so it has geometry id 0 in both, which alpha's hash uses).
const std::string kSphere = R"(
AttributeBegin
  Translate 0.1 -0.05 0.02
  Scale 1 0.8 1.2
  Shape "sphere" "float radius" 0.5 "float alpha" 0.6
AttributeEnd
)";
// Two more shapes far from every ray's path (their boxes hold none of the rays' points): with them the
// world has three analytic shapes, more than kDirectShapes, so Embree traverses all.
const std::string kFarShapes = R"(
AttributeBegin
  Translate 50 50 50
  Shape "sphere" "float radius" 0.5
  Translate 5 0 0
  Shape "disk" "float radius" 0.5
AttributeEnd
)";

TEST(DirectShapes, HitsOcclusionAndCrossingsAsEmbreeFindsThem) {
    static_assert(Accelerator::kDirectShapes < 3, "the Embree world below must have more shapes");
    const std::string wall = "Shape \"trianglemesh\" \"point3 P\" [-3 -3 -0.3 3 -3 -0.3 3 3 -0.3 -3 3 -0.3] "
                             "\"integer indices\" [0 1 2 0 2 3]\n";
    for (bool passable : {false, true}) {
        std::string material = passable ? "Material \"interface\"\n" : "Material \"diffuse\"\n";
        auto direct = scene_of(material + kSphere + "Material \"diffuse\"\n" + wall);
        auto embree = scene_of(material + kSphere + kFarShapes + "Material \"diffuse\"\n" + wall);
        PCG32 rng(11);
        int hits = 0, sphere_hits = 0, crossings = 0;
        for (int i = 0; i < 20000; ++i) {
            Ray ray = random_ray(rng);
            Accelerator::Found a, b;
            bool fa = direct->find(ray, &a), fb = embree->find(ray, &b);
            ASSERT_EQ(fa, fb) << i;
            if (fa) {
                ++hits;
                ASSERT_EQ(a.rh.hit.geomID == 0, b.rh.hit.geomID == 0) << i;
                ASSERT_EQ(a.t(), b.t()) << i;
                if (a.rh.hit.geomID == 0) {
                    ++sphere_hits;
                    SurfaceHit ha, hb;
                    ASSERT_TRUE(direct->complete(a, ray, &ha) && embree->complete(b, ray, &hb));
                    EXPECT_EQ(ha.p, hb.p);
                    EXPECT_EQ(ha.n, hb.n);
                }
            }
            Ray segment = ray;
            segment.tmax = 1; // ends near the origin: inside, beyond or before the sphere
            ASSERT_EQ(direct->occluded(segment), embree->occluded(segment)) << i;
            Accelerator::ShadowCrossings xa, xb;
            bool pa = direct->accelerator.shadow_crossings(segment, &xa);
            bool pb = embree->accelerator.shadow_crossings(segment, &xb);
            ASSERT_EQ(pa, pb) << i;
            if (!pa) continue;
            ASSERT_EQ(xa.n, xb.n) << i;
            for (int k = 0; k < xa.n; ++k) {
                EXPECT_EQ(xa.hits[k].t(), xb.hits[k].t());
                EXPECT_EQ(xa.hits[k].rh.hit.geomID, xb.hits[k].rh.hit.geomID);
            }
            crossings += xa.n;
        }
        // The alpha of 0.6 lets 40% of the sphere's crossings through; both worlds must agree on which.
        EXPECT_GT(sphere_hits, 2000);
        EXPECT_GT(hits, sphere_hits + 2000);
        if (passable)
            EXPECT_GT(crossings, 1000);
        else
            EXPECT_EQ(crossings, 0);
    }
}

TEST(MediumBeyond, NamesTheMediumTheCompletedHitNames) {
    const std::string world = R"(
MakeNamedMedium "a" "string type" "homogeneous" "rgb sigma_a" [1 1 1] "rgb sigma_s" [0 0 0]
MakeNamedMedium "b" "string type" "homogeneous" "rgb sigma_a" [2 2 2] "rgb sigma_s" [0 0 0]
Material "interface"
ObjectBegin "slab"
  MediumInterface "a" "b"
  Shape "trianglemesh" "point3 P" [-0.3 -0.3 0 0.3 -0.3 0 0.3 0.3 0 -0.3 0.3 0] "integer indices" [0 1 2 0 2 3]
ObjectEnd
AttributeBegin
  MediumInterface "a" "b"
  Translate -0.6 0 0
  Rotate 30 1 1 0
  Scale 1 0.7 1.3
  Shape "sphere" "float radius" 0.3
AttributeEnd
AttributeBegin
  MediumInterface "b" "a"
  ReverseOrientation
  Translate 0.6 0 0
  Shape "sphere" "float radius" 0.25
AttributeEnd
AttributeBegin
  MediumInterface "a" ""
  Translate 0 0.6 0
  Rotate 70 1 0 0
  Shape "disk" "float radius" 0.3
  Translate 0 0 -0.5
  Scale 1 1 -1
  Shape "cylinder" "float radius" 0.2 "float zmin" -0.2 "float zmax" 0.2
AttributeEnd
AttributeBegin
  MediumInterface "" "b"
  Translate 0 -0.6 0
  Rotate 40 0 1 1
  Shape "trianglemesh" "point3 P" [-0.3 -0.3 0 0.3 -0.3 0 0.3 0.3 0 -0.3 0.3 0] "integer indices" [0 1 2 0 2 3]
AttributeEnd
AttributeBegin
  Translate 0 0 0.7
  Rotate 120 0 1 1
  Scale -1 1 1
  ObjectInstance "slab"
AttributeEnd
)";
    auto scene = scene_of(world);
    PCG32 rng(5);
    int interfaces = 0, instanced = 0;
    for (int i = 0; i < 40000; ++i) {
        Ray ray = random_ray(rng);
        Accelerator::Found found;
        if (!scene->find(ray, &found)) continue;
        SurfaceHit hit;
        ASSERT_TRUE(scene->complete(found, ray, &hit));
        const Medium* beyond = nullptr;
        ASSERT_TRUE(scene->accelerator.medium_beyond(found, ray, &beyond));
        EXPECT_EQ(beyond, hit.medium_for(ray.d)) << i;
        if (hit.medium_interface) ++interfaces;
        if (found.rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID && hit.medium_interface) ++instanced;
    }
    EXPECT_GT(interfaces, 5000);
    EXPECT_GT(instanced, 100);
}

} // namespace
} // namespace illum

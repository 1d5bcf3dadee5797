// A furball: N random hairs (cubic Bézier curves, 0.3 long, width 0.01 at the root to 0.002 at the tip)
// growing from a unit sphere, hit by rays from a sphere of radius 4 aimed into the ball. Closest-hit rays per
// second, one thread, for
//   illum      Accelerator::intersect: Embree's flat Bézier curves plus filling the hit (u, v, frame);
//   embree     Accelerator::intersect_distance: the same scene, rtcIntersect1 alone;
//   raw flat   a bare Embree scene of the same curves (RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE), rtcIntersect1;
//   raw round  the same as Embree's round (swept-sphere) curves, which illum does not use (curves.h);
// and shadow rays (Accelerator::occluded). Arguments: the number of hairs.
#include <benchmark/benchmark.h>

#include <embree3/rtcore.h>
#include <map>
#include <memory>
#include <vector>

#include "illum/geometry/accelerator.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

std::unique_ptr<Curves> furball(int n) {
    auto c = std::make_unique<Curves>();
    c->type = CurveType::Cylinder;
    PCG32 rng(11);
    for (int i = 0; i < n; ++i) {
        Vector3f root = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        Vector3f bend = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}) * 0.35f;
        Vector3f dir = normalize(root + bend);
        Vector3f droop = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}) * 0.08f;
        Point3f p0(root);
        c->cp.push_back({p0, p0 + root * 0.1f, p0 + dir * 0.2f + droop * 0.5f, p0 + dir * 0.3f + droop});
        c->width.push_back({0.01f, 0.002f});
    }
    return c;
}

std::vector<Ray> rays_into_ball(int n) {
    PCG32 rng(12);
    std::vector<Ray> rays(static_cast<std::size_t>(n));
    for (Ray& r : rays) {
        r.o = Point3f(sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}) * 4);
        Point3f target(sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}) *
                       (1.4f * std::cbrt(rng.uniform_float())));
        r.d = normalize(target - r.o);
        r.tmax = kInfinity;
    }
    return rays;
}

// One accelerator per size, built once (building 1M hairs takes seconds).
const Accelerator& accelerator(int n) {
    static std::map<int, std::unique_ptr<Accelerator>> cache;
    auto& a = cache[n];
    if (!a) {
        a = std::make_unique<Accelerator>();
        a->add_curves(furball(n), nullptr);
        a->commit();
    }
    return *a;
}

// A bare Embree scene of the furball's curves as `type`.
struct RawScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    RawScene(int n, RTCGeometryType type) {
        auto c = furball(n);
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry g = rtcNewGeometry(device, type);
        std::size_t m = c->segment_count();
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 16, 4 * m));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, 4, m));
        for (std::size_t i = 0; i < m; ++i) {
            idx[i] = unsigned(4 * i);
            for (int k = 0; k < 4; ++k) {
                float* q = v + 16 * i + 4 * std::size_t(k);
                Point3f p = c->cp[i][std::size_t(k)];
                q[0] = p.x;
                q[1] = p.y;
                q[2] = p.z;
                q[3] = 0.5f * (c->width[i][0] + (c->width[i][1] - c->width[i][0]) * float(k) / 3);
            }
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    ~RawScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

void BM_FurballIllum(benchmark::State& state) {
    const Accelerator& acc = accelerator(int(state.range(0)));
    auto rays = rays_into_ball(1 << 16);
    std::size_t hits = 0;
    for (auto _ : state)
        for (const Ray& r : rays) {
            SurfaceHit h;
            hits += acc.intersect(r, &h);
        }
    benchmark::DoNotOptimize(hits);
    state.counters["hit_fraction"] = double(hits) / double(state.iterations() * rays.size());
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
}
BENCHMARK(BM_FurballIllum)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_FurballEmbreeOnly(benchmark::State& state) {
    const Accelerator& acc = accelerator(int(state.range(0)));
    auto rays = rays_into_ball(1 << 16);
    float sum = 0;
    for (auto _ : state)
        for (const Ray& r : rays) sum += std::min(acc.intersect_distance(r), 100.0f);
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
}
BENCHMARK(BM_FurballEmbreeOnly)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_FurballShadow(benchmark::State& state) {
    const Accelerator& acc = accelerator(int(state.range(0)));
    auto rays = rays_into_ball(1 << 16);
    std::size_t blocked = 0;
    for (auto _ : state)
        for (const Ray& r : rays) blocked += acc.occluded(r);
    benchmark::DoNotOptimize(blocked);
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
}
BENCHMARK(BM_FurballShadow)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void raw(benchmark::State& state, RTCGeometryType type) {
    RawScene s(int(state.range(0)), type);
    auto rays = rays_into_ball(1 << 16);
    std::size_t hits = 0;
    for (auto _ : state)
        for (const Ray& r : rays) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            RTCRayHit rh;
            rh.ray = {r.o.x, r.o.y, r.o.z, 0, r.d.x, r.d.y, r.d.z, 0, kInfinity, 0xffffffffu, 0, 0};
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(s.scene, &ctx, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    benchmark::DoNotOptimize(hits);
    state.counters["hit_fraction"] = double(hits) / double(state.iterations() * rays.size());
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
}
void BM_FurballRawFlat(benchmark::State& state) { raw(state, RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE); }
void BM_FurballRawRound(benchmark::State& state) { raw(state, RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE); }
BENCHMARK(BM_FurballRawFlat)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FurballRawRound)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace illum

#include "illum/geometry/accelerator.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "illum/math/rng.h"
#include "illum/util/error.h"
#include <cstring>

namespace illum {

namespace {

// Embree calls this from C code, so it must not throw: report, and let the caller's checks fail.
void embree_error(void*, RTCError code, const char* message) {
    if (code == RTC_ERROR_NONE) return;
    fmt::print(stderr, "warning: Embree error {}: {}\n", int(code), message ? message : "");
}

// User geometry callbacks for disks (single rays only: illum traces rays one at a time).
void disk_bounds(const RTCBoundsFunctionArguments* args) {
    auto* disk = static_cast<const DiskShape*>(args->geometryUserPtr);
    Bounds3f b = disk->bounds();
    args->bounds_o->lower_x = b.lo.x;
    args->bounds_o->lower_y = b.lo.y;
    args->bounds_o->lower_z = b.lo.z;
    args->bounds_o->upper_x = b.hi.x;
    args->bounds_o->upper_y = b.hi.y;
    args->bounds_o->upper_z = b.hi.z;
}

void disk_intersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* disk = static_cast<const DiskShape*>(args->geometryUserPtr);
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    Ray ray{{rh->ray.org_x, rh->ray.org_y, rh->ray.org_z}, {rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z}, rh->ray.tfar};
    auto t = disk->intersect(ray);
    if (!t || *t <= rh->ray.tnear) return;
    rh->ray.tfar = *t;
    rh->hit.u = 0;
    rh->hit.v = 0;
    rh->hit.Ng_x = rh->hit.Ng_y = 0;
    rh->hit.Ng_z = 1;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    rh->hit.instID[0] = args->context->instID[0];
}

void disk_occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* disk = static_cast<const DiskShape*>(args->geometryUserPtr);
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    Ray ray{{r->org_x, r->org_y, r->org_z}, {r->dir_x, r->dir_y, r->dir_z}, r->tfar};
    auto t = disk->intersect(ray);
    if (t && *t > r->tnear) r->tfar = -std::numeric_limits<float>::infinity();
}

RTCRay to_embree(const Ray& ray) {
    RTCRay r;
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    // Not 0: Embree flushes denormals, so an origin stepped one ulp off an exact coordinate (z = 0) can
    // read as lying on the surface and report t = 0. No true hit lies closer than the smallest normal float.
    r.tnear = std::numeric_limits<float>::min();
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.time = 0;
    r.tfar = ray.tmax;
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
    return r;
}

} // namespace

Accelerator::Accelerator() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw Error(fmt::format("cannot create an Embree device (error {})", int(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(device_, embree_error, nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
}

Accelerator::~Accelerator() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

std::uint32_t Accelerator::attach(RTCGeometry geom, Record record) {
    rtcCommitGeometry(geom);
    std::uint32_t id = rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    if (id != records_.size()) throw Error("Embree returned an unexpected geometry id");
    records_.push_back(std::move(record));
    return id;
}

// The alpha test at a candidate hit (both closest-hit and shadow rays): evaluate the alpha texture at the
// hit's uv and reject the hit unless a uniform number from a hash of the ray is below alpha.
void Accelerator::alpha_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    const auto* cut = static_cast<const AlphaCutout*>(args->geometryUserPtr);
    const auto* h = reinterpret_cast<const RTCHit*>(args->hit);
    const auto* r = reinterpret_cast<const RTCRay*>(args->ray);
    const TriangleMesh& m = *cut->mesh;
    std::uint32_t tri = h->primID;
    float b1 = h->u, b2 = h->v, b0 = 1 - b1 - b2;
    SurfaceHit sh;
    auto v = m.vertices(tri);
    sh.p = barycentric(v[0], v[1], v[2], b0, b1, b2);
    if (!m.uv.empty()) {
        Point2f t0 = m.uv[m.indices[3 * tri]], t1 = m.uv[m.indices[3 * tri + 1]], t2 = m.uv[m.indices[3 * tri + 2]];
        sh.uv = {b0 * t0.x + b1 * t1.x + b2 * t2.x, b0 * t0.y + b1 * t1.y + b2 * t2.y};
    } else {
        sh.uv = {b1 + b2, b2}; // the default (0,0), (1,0), (1,1) parameterisation
    }
    float a = cut->alpha->evaluate(sh);
    if (a >= 1) return;
    if (a <= 0) {
        args->valid[0] = 0;
        return;
    }
    auto bits = [](float f) {
        std::uint32_t u;
        std::memcpy(&u, &f, sizeof u);
        return u;
    };
    std::uint64_t key = hash(bits(r->org_x), bits(r->org_y), bits(r->org_z), bits(r->dir_x), bits(r->dir_y),
                             bits(r->dir_z), tri);
    if (float(key >> 40) * 0x1p-24f > a) args->valid[0] = 0;
}

std::uint32_t Accelerator::add_mesh(std::unique_ptr<TriangleMesh> mesh, const Material* material,
                                    std::vector<const Light*> lights, const FloatTexture* alpha) {
    if (mesh->face_normals.size() != mesh->triangle_count()) mesh->finalize();
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh->p.size()));
    for (std::size_t i = 0; i < mesh->p.size(); ++i) {
        v[3 * i] = mesh->p[i].x;
        v[3 * i + 1] = mesh->p[i].y;
        v[3 * i + 2] = mesh->p[i].z;
        bounds_.extend(mesh->p[i]);
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), mesh->triangle_count()));
    std::copy(mesh->indices.begin(), mesh->indices.end(), idx);
    std::unique_ptr<AlphaCutout> cutout;
    if (alpha) {
        cutout = std::make_unique<AlphaCutout>(AlphaCutout{mesh.get(), alpha});
        rtcSetGeometryUserData(geom, cutout.get());
        rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
        rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
    }
    Record r{Kind::Mesh, std::move(mesh), nullptr, nullptr, material, std::move(lights), std::move(cutout)};
    return attach(geom, std::move(r));
}

std::uint32_t Accelerator::add_sphere(std::unique_ptr<SphereShape> sphere, const Material* material,
                                      const Light* light) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = sphere->center().x;
    v[1] = sphere->center().y;
    v[2] = sphere->center().z;
    v[3] = sphere->radius();
    bounds_.extend(sphere->bounds());
    std::vector<const Light*> lights;
    if (light) lights.push_back(light);
    Record r{Kind::Sphere, nullptr, std::move(sphere), nullptr, material, std::move(lights)};
    return attach(geom, std::move(r));
}

std::uint32_t Accelerator::add_disk(std::unique_ptr<DiskShape> disk, const Material* material, const Light* light) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    rtcSetGeometryUserData(geom, disk.get());
    rtcSetGeometryBoundsFunction(geom, disk_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, disk_intersect);
    rtcSetGeometryOccludedFunction(geom, disk_occluded);
    bounds_.extend(disk->bounds());
    std::vector<const Light*> lights;
    if (light) lights.push_back(light);
    Record r{Kind::Disk, nullptr, nullptr, std::move(disk), material, std::move(lights)};
    return attach(geom, std::move(r));
}

void Accelerator::commit() { rtcCommitScene(scene_); }

bool Accelerator::intersect(const Ray& ray, SurfaceHit* hit) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray = to_embree(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

    const Record& rec = records_[rh.hit.geomID];
    float t = rh.ray.tfar;
    switch (rec.kind) {
    case Kind::Mesh: rec.mesh->fill_hit(rh.hit.primID, rh.hit.u, rh.hit.v, t, ray, hit); break;
    case Kind::Sphere: rec.sphere->fill_hit(t, ray, hit); break;
    case Kind::Disk: rec.disk->fill_hit(t, ray, hit); break;
    }
    hit->geom_id = rh.hit.geomID;
    hit->prim_id = rh.hit.primID;
    hit->material = rec.material;
    hit->area_light = rec.lights.empty() ? nullptr : rec.lights[rec.kind == Kind::Mesh ? rh.hit.primID : 0];
    return true;
}

float Accelerator::intersect_distance(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray = to_embree(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
}

bool Accelerator::occluded(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r = to_embree(ray);
    rtcOccluded1(scene_, &ctx, &r);
    return r.tfar < 0 && std::isinf(r.tfar);
}

const TriangleMesh* Accelerator::mesh(std::uint32_t id) const { return records_.at(id).mesh.get(); }
const SphereShape* Accelerator::sphere(std::uint32_t id) const { return records_.at(id).sphere.get(); }
const DiskShape* Accelerator::disk(std::uint32_t id) const { return records_.at(id).disk.get(); }

std::size_t Accelerator::triangle_count() const {
    std::size_t n = 0;
    for (auto& r : records_)
        if (r.mesh) n += r.mesh->triangle_count();
    return n;
}

} // namespace illum

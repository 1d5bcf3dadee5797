#include "illum/geometry/accelerator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "illum/geometry/motion_steps.h"
#include "illum/geometry/sphere.h"
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

// pbrt-v4's stochastic alpha test: keep a hit of alpha a with probability a, by a uniform number hashed
// from the ray, the geometry and the crossing (a triangle, or a root of an analytic shape), so the
// decision is deterministic per ray and independent between the surfaces a ray crosses.
bool alpha_keeps(float a, const RTCRay& r, std::uint32_t geom_id, std::uint32_t crossing) {
    if (a >= 1) return true;
    if (a <= 0) return false;
    auto bits = [](float f) {
        std::uint32_t u;
        std::memcpy(&u, &f, sizeof u);
        return u;
    };
    std::uint64_t key = hash(bits(r.org_x), bits(r.org_y), bits(r.org_z), bits(r.dir_x), bits(r.dir_y),
                             bits(r.dir_z), geom_id, crossing);
    return float(key >> 40) * 0x1p-24f <= a;
}

// Whether a crossing of an analytic shape survives its alpha test.
bool shape_keeps(const AnalyticShape& shape, const Crossing& c, const RTCRay& r, std::uint32_t geom_id) {
    if (!shape.alpha()) return true;
    return alpha_keeps(shape.alpha()->evaluate(shape.alpha_point(c)), r, geom_id, std::uint32_t(c.root));
}

// A user geometry primitive's box, as Embree asks for it.
void write_bounds(const Bounds3f& b, RTCBounds* out) {
    out->lower_x = b.lo.x;
    out->lower_y = b.lo.y;
    out->lower_z = b.lo.z;
    out->upper_x = b.hi.x;
    out->upper_y = b.hi.y;
    out->upper_z = b.hi.z;
}

// User geometry callbacks for analytic shapes: intersection for single rays and packets (each_ray),
// occlusion for single rays (illum traces shadow rays one at a time).
void shape_bounds(const RTCBoundsFunctionArguments* args) {
    write_bounds(static_cast<const AnalyticShape*>(args->geometryUserPtr)->bounds(), args->bounds_o);
}

// The crossings of an analytic shape within the ray's (tnear, tfar) that pass the alpha test, nearest first;
// returns how many (at most 2). pbrt-v4 continues the ray past a rejected one, so a clipped or cut-out near
// side shows the far side.
int kept_crossings(const AnalyticShape& shape, const RTCRay& r, std::uint32_t geom_id, float t_out[2]) {
    Ray ray{{r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tfar};
    Crossing c[2];
    int n = shape.crossings(ray, r.tnear, r.tfar, c), kept = 0;
    for (int i = 0; i < n; ++i) {
        float t = float(c[i].t);
        if (!(t > r.tnear && t < r.tfar) || !shape_keeps(shape, c[i], r, geom_id)) continue;
        t_out[kept++] = t;
    }
    return kept;
}

// The shape's nearest kept crossing, if any, made the ray's hit.
void record_shape_hit(const AnalyticShape& shape, RTCRayHit* rh, std::uint32_t geom_id, std::uint32_t prim_id,
                      std::uint32_t inst_id) {
    float t[2];
    if (kept_crossings(shape, rh->ray, geom_id, t) == 0) return;
    rh->ray.tfar = t[0];
    rh->hit.u = 0;
    rh->hit.v = 0;
    rh->hit.Ng_x = rh->hit.Ng_y = 0;
    rh->hit.Ng_z = 1;
    rh->hit.primID = prim_id;
    rh->hit.geomID = geom_id;
    rh->hit.instID[0] = inst_id;
}

// An intersect callback's single-ray work on every valid ray of what Embree passes: one ray (N = 1) or a
// packet (Accelerator::find_packet), whose lanes are copied out and, where `single` made a hit, back.
template <class Single>
void each_ray(const RTCIntersectFunctionNArguments* args, Single&& single) {
    if (args->N == 1) {
        if (args->valid[0]) single(*reinterpret_cast<RTCRayHit*>(args->rayhit));
        return;
    }
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        RTCRayHit rh = rtcGetRayHitFromRayHitN(args->rayhit, args->N, i);
        const float tfar = rh.ray.tfar;
        single(rh);
        if (rh.ray.tfar == tfar) continue;
        RTCRayN_tfar(RTCRayHitN_RayN(args->rayhit, args->N), args->N, i) = rh.ray.tfar;
        rtcCopyHitToHitN(RTCRayHitN_HitN(args->rayhit, args->N), &rh.hit, args->N, i);
    }
}

// The same for a filter callback: `accepts` sees each valid candidate hit as a single ray and hit (the
// ray's tfar at the candidate), and a rejected one is marked invalid.
template <class Accepts>
void each_candidate(const RTCFilterFunctionNArguments* args, Accepts&& accepts) {
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        const RTCRay r = args->N == 1 ? *reinterpret_cast<const RTCRay*>(args->ray)
                                      : rtcGetRayFromRayN(args->ray, args->N, i);
        const RTCHit h = args->N == 1 ? *reinterpret_cast<const RTCHit*>(args->hit)
                                      : rtcGetHitFromHitN(args->hit, args->N, i);
        if (!accepts(r, h)) args->valid[i] = 0;
    }
}

void shape_intersect(const RTCIntersectFunctionNArguments* args) {
    each_ray(args, [&](RTCRayHit& rh) {
        record_shape_hit(*static_cast<const AnalyticShape*>(args->geometryUserPtr), &rh, args->geomID,
                         args->primID, args->context->instID[0]);
    });
}

// Whether a user geometry's crossing at t (surface coordinates u, v) occludes the ray: a context filter
// (Accelerator::shadow_crossings) sees it as Embree shows it a triangle's, with the ray's tfar at the hit,
// and may let the ray pass; without one every crossing occludes.
bool occlusion_accepted(const RTCOccludedFunctionNArguments* args, RTCRay* r, float t, float u, float v) {
    if (!args->context->filter) return true;
    RTCHit h{};
    h.u = u;
    h.v = v;
    h.Ng_z = 1;
    h.primID = args->primID;
    h.geomID = args->geomID;
    h.instID[0] = args->context->instID[0];
    int valid = -1;
    const float tfar = r->tfar;
    r->tfar = t;
    RTCFilterFunctionNArguments fa{&valid,
                                   args->geometryUserPtr,
                                   args->context,
                                   reinterpret_cast<RTCRayN*>(r),
                                   reinterpret_cast<RTCHitN*>(&h),
                                   1};
    rtcFilterOcclusion(args, &fa);
    r->tfar = tfar;
    return valid != 0;
}

void shape_occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    float t[2];
    int n = kept_crossings(*shape, *r, args->geomID, t);
    for (int i = 0; i < n; ++i) {
        if (!occlusion_accepted(args, r, t[i], 0, 0)) continue;
        r->tfar = -std::numeric_limits<float>::infinity();
        return;
    }
}

// User geometry callbacks for bilinear patches: one primitive per patch.
void patch_bounds(const RTCBoundsFunctionArguments* args) {
    auto* g = static_cast<const PatchUserData*>(args->geometryUserPtr);
    write_bounds(g->mesh->patch_bounds(args->primID), args->bounds_o);
}

// The patch's crossing of the ray within (tnear, tfar) that passes the alpha test.
std::optional<PatchCrossing> patch_crossing(const PatchUserData& g, std::uint32_t prim, const RTCRay& r,
                                            std::uint32_t geom_id) {
    auto c = g.mesh->corners(prim);
    auto x = intersect_bilinear_patch({r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tfar, c[0],
                                      c[1], c[2], c[3]);
    if (!x || !(x->t > r.tnear)) return std::nullopt;
    if (g.alpha) {
        SurfaceHit h;
        h.p = lerp(x->u, lerp(x->v, c[0], c[2]), lerp(x->v, c[1], c[3]));
        h.n = h.ns = g.mesh->geometric_normal(prim, x->u, x->v);
        h.uv = g.mesh->texture_uv(prim, x->u, x->v);
        h.face_index = g.mesh->face_index(prim);
        if (!alpha_keeps(g.alpha->evaluate(h), r, geom_id, prim)) return std::nullopt;
    }
    return x;
}

void patch_intersect(const RTCIntersectFunctionNArguments* args) {
    auto* g = static_cast<const PatchUserData*>(args->geometryUserPtr);
    each_ray(args, [&](RTCRayHit& rh) {
        auto x = patch_crossing(*g, args->primID, rh.ray, args->geomID);
        if (!x) return;
        rh.ray.tfar = x->t;
        rh.hit.u = x->u;
        rh.hit.v = x->v;
        rh.hit.Ng_x = rh.hit.Ng_y = 0;
        rh.hit.Ng_z = 1;
        rh.hit.primID = args->primID;
        rh.hit.geomID = args->geomID;
        rh.hit.instID[0] = args->context->instID[0];
    });
}

void patch_occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* g = static_cast<const PatchUserData*>(args->geometryUserPtr);
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    // A patch meets a line at most twice. A context filter (Accelerator::shadow_crossings) may let the ray
    // through the first crossing; the second is then searched beyond it.
    RTCRay rest = *r;
    float t0 = 0;
    for (int k = 0; k < 2; ++k) {
        auto x = patch_crossing(*g, args->primID, rest, args->geomID);
        if (!x) return;
        const float t = t0 + x->t;
        if (!occlusion_accepted(args, r, t, x->u, x->v)) {
            rest.org_x = r->org_x + r->dir_x * t;
            rest.org_y = r->org_y + r->dir_y * t;
            rest.org_z = r->org_z + r->dir_z * t;
            rest.tfar = r->tfar - t;
            t0 = t;
            continue;
        }
        r->tfar = -std::numeric_limits<float>::infinity();
        return;
    }
}

// Embree 3 asserts on a ray whose origin or direction has a NaN component or one beyond ±1.844e18 (its
// FLT_LARGE), or whose tfar is NaN, and Debian's build keeps the assertion: the process aborts (a shadow
// ray towards a point light at z = 1e19 did, found by fuzz/pbrt_scene_fuzz.cpp). Such a ray cannot be
// traced; it hits nothing.
bool traceable(const RTCRay& r) {
    constexpr float kEmbreeLarge = 1.844E18f;
    for (float v : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z})
        if (!(std::abs(v) <= kEmbreeLarge)) return false;
    return !std::isnan(r.tfar);
}

// Each field is read on its own (a relaxed atomic load, which the compiler does not merge with its
// neighbours; on x86 a plain move): the ray has usually just been stored by its maker, field by field, and
// one wide load spanning several of those stores waits for them to reach the cache (a store-forwarding
// stall, util/in_place.h), as the vectoriser's merged load of o.y..d.y did in every shadow ray.
float field(const float& f) {
    return std::atomic_ref<float>(const_cast<float&>(f)).load(std::memory_order_relaxed);
}

RTCRay to_embree(const Ray& ray, float time) {
    RTCRay r;
    r.org_x = field(ray.o.x);
    r.org_y = field(ray.o.y);
    r.org_z = field(ray.o.z);
    // Not 0: Embree flushes denormals, so an origin stepped one ulp off an exact coordinate (z = 0) can
    // read as lying on the surface and report t = 0. No true hit lies closer than the smallest normal float.
    r.tnear = std::numeric_limits<float>::min();
    r.dir_x = field(ray.d.x);
    r.dir_y = field(ray.d.y);
    r.dir_z = field(ray.d.z);
    r.time = time;
    r.tfar = field(ray.tmax);
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
    return r;
}

} // namespace

Accelerator::Accelerator() {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        throw Error(
            fmt::format("cannot create an Embree device (error {})", int(rtcGetDeviceError(nullptr))));
    rtcSetDeviceErrorFunction(device_, embree_error, nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    inv_shutter_ = 0; // nothing moves yet (add_moving_instance)
}

Accelerator::~Accelerator() {
    for (auto& p : prototypes_)
        if (p->scene) rtcReleaseScene(p->scene);
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
}

std::uint32_t Accelerator::attach(RTCGeometry geom, Record record) {
    rtcCommitGeometry(geom);
    RTCScene scene = building_ ? building_->scene : scene_;
    std::vector<Record>& records = building_ ? building_->records : records_;
    std::uint32_t id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    if (id != records.size()) throw Error("Embree returned an unexpected geometry id");
    records.push_back(std::move(record));
    return id;
}

std::uint32_t Accelerator::begin_prototype() {
    if (building_) throw Error("nested object instance definitions");
    prototypes_.push_back(std::make_unique<Prototype>());
    building_ = prototypes_.back().get();
    building_->scene = rtcNewScene(device_);
    rtcSetSceneBuildQuality(building_->scene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(building_->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    return std::uint32_t(prototypes_.size() - 1);
}

void Accelerator::end_prototype() {
    if (!building_) return;
    flush_curves();
    rtcCommitScene(building_->scene);
    building_ = nullptr;
}

void Accelerator::add_instance(std::uint32_t prototype, const Transform& world_from_instance) {
    const Prototype& proto = *prototypes_.at(prototype);
    if (proto.records.empty()) return; // nothing to place
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, proto.scene);
    rtcSetGeometryTimeStepCount(geom, 1);
    float xfm[12];
    const Matrix4& m = world_from_instance.matrix();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) xfm[4 * r + c] = float(m(r, c));
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
    for (float x : {proto.bounds.lo.x, proto.bounds.hi.x})
        for (float y : {proto.bounds.lo.y, proto.bounds.hi.y})
            for (float z : {proto.bounds.lo.z, proto.bounds.hi.z})
                bounds_.extend(world_from_instance(Point3f{x, y, z}));
    Record r;
    r.kind = Kind::Instance;
    r.prototype = prototype;
    r.world_from_instance = world_from_instance;
    Prototype* saved = building_;
    building_ = nullptr; // instances live in the world scene
    attach(geom, std::move(r));
    building_ = saved;
}

void Accelerator::set_shutter(float open, float close) {
    shutter_open_ = open;
    shutter_close_ = close;
    inv_shutter_ = 0; // until something moves
}

float Accelerator::embree_time(float time) const {
    // Without moving geometry Embree ignores the time: a still scene skips the arithmetic.
    if (inv_shutter_ == 0) return 0;
    return std::clamp((time - shutter_open_) * inv_shutter_, 0.0f, 1.0f);
}

template <class WorldAt>
void Accelerator::place_moving(std::uint32_t prototype, const std::vector<TransformComponents>& steps,
                               WorldAt&& world_at, double t0, double t1) {
    const Prototype& proto = *prototypes_.at(prototype);
    if (shutter_close_ > shutter_open_) inv_shutter_ = 1 / (shutter_close_ - shutter_open_);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geom, proto.scene);
    rtcSetGeometryTimeStepCount(geom, unsigned(steps.size()));
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const TransformComponents& c = steps[i];
        RTCQuaternionDecomposition qd;
        rtcInitQuaternionDecomposition(&qd);
        const Matrix3d& u = c.scale;
        rtcQuaternionDecompositionSetScale(&qd, float(u[0]), float(u[4]), float(u[8]));
        rtcQuaternionDecompositionSetSkew(&qd, float(u[1]), float(u[2]), float(u[5]));
        rtcQuaternionDecompositionSetQuaternion(&qd, float(c.rotation.w), float(c.rotation.x),
                                                float(c.rotation.y), float(c.rotation.z));
        rtcQuaternionDecompositionSetTranslation(&qd, float(c.translation[0]), float(c.translation[1]),
                                                 float(c.translation[2]));
        rtcSetGeometryTransformQuaternion(geom, unsigned(i), &qd);
    }
    // The world bounds (for the lights that need them) from the corners along the motion.
    for (int i = 0; i <= 64; ++i) {
        Transform w = world_at(t0 + (t1 - t0) * i / 64);
        for (float x : {proto.bounds.lo.x, proto.bounds.hi.x})
            for (float y : {proto.bounds.lo.y, proto.bounds.hi.y})
                for (float z : {proto.bounds.lo.z, proto.bounds.hi.z}) bounds_.extend(w(Point3f{x, y, z}));
    }
    Record r;
    r.kind = Kind::Instance;
    r.prototype = prototype;
    r.world_from_instance = world_at(t0);
    r.moving = geom;
    Prototype* saved = building_;
    building_ = nullptr;
    attach(geom, std::move(r));
    building_ = saved;
}

std::uint32_t Accelerator::add_moving_instance(std::uint32_t prototype,
                                               const AnimatedTransform& world_from_instance) {
    if (prototypes_.at(prototype)->records.empty()) return kNoInstance;
    place_moving(
        prototype, motion_steps(world_from_instance, shutter_open_, shutter_close_),
        [&](double t) { return world_from_instance.interpolate(t); }, world_from_instance.start_time(),
        world_from_instance.end_time());
    return std::uint32_t(records_.size() - 1);
}

std::optional<Transform> Accelerator::moving_transform(std::uint32_t instance, float time) const {
    const Record& inst = records_.at(instance);
    if (!inst.moving) return inst.world_from_instance;
    float xfm[12];
    rtcGetGeometryTransform(inst.moving, embree_time(time), RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
    Matrix4 m = Matrix4::identity();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = xfm[4 * r + c];
    auto inv = inverse(m);
    if (!inv) return std::nullopt;
    return Transform(m, *inv);
}

void Accelerator::add_moving_instance(std::uint32_t prototype, const AnimatedTransform& outer,
                                      const AnimatedTransform& inner) {
    if (prototypes_.at(prototype)->records.empty()) return;
    // Bounded over the moving times (each motion is still outside its own).
    double t0 = inner.start_time(), t1 = inner.end_time();
    if (outer.is_animated()) t0 = std::min(t0, outer.start_time()), t1 = std::max(t1, outer.end_time());
    place_moving(
        prototype, motion_steps(outer, inner, shutter_open_, shutter_close_),
        [&](double t) { return outer.interpolate(t) * inner.interpolate(t); }, t0, t1);
}

// The alpha test at a candidate hit (both closest-hit and shadow rays): evaluate the alpha texture at the
// hit's uv and reject the hit unless a uniform number from a hash of the ray is below alpha.
void Accelerator::alpha_filter(const RTCFilterFunctionNArguments* args) {
    const auto* cut = static_cast<const AlphaCutout*>(args->geometryUserPtr);
    const TriangleMesh& m = *cut->mesh;
    each_candidate(args, [&](const RTCRay& r, const RTCHit& h) {
        std::uint32_t tri = h.primID;
        float b1 = h.u, b2 = h.v, b0 = 1 - b1 - b2;
        SurfaceHit sh;
        auto v = m.vertices(tri);
        sh.p = barycentric(v[0], v[1], v[2], b0, b1, b2);
        if (!m.uv.empty()) {
            Point2f t0 = m.uv[m.indices[3 * tri]], t1 = m.uv[m.indices[3 * tri + 1]],
                    t2 = m.uv[m.indices[3 * tri + 2]];
            sh.uv = {b0 * t0.x + b1 * t1.x + b2 * t2.x, b0 * t0.y + b1 * t1.y + b2 * t2.y};
        } else {
            sh.uv = {b1 + b2, b2}; // the default (0,0), (1,0), (1,1) parameterisation
        }
        sh.face_index = m.face_index(tri);
        return alpha_keeps(cut->alpha->evaluate(sh), r, h.geomID, tri);
    });
}

// The same for a curve (pbrt-v4's GeometricPrimitive tests every shape's hit, curves' too): the alpha
// texture at the hit's (u, v) as Curves::fill_hit gives them, u along the segment and v across its width.
void Accelerator::curve_alpha_filter(const RTCFilterFunctionNArguments* args) {
    const auto* cut = static_cast<const AlphaCutout*>(args->geometryUserPtr);
    each_candidate(args, [&](const RTCRay& r, const RTCHit& h) {
        // In a filter function the ray's tfar is the candidate hit's distance.
        Ray ray{{r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tfar};
        SurfaceHit sh;
        cut->curves->fill_hit(h.primID, h.u, r.tfar, ray, &sh);
        return alpha_keeps(cut->alpha->evaluate(sh), r, h.geomID, h.primID);
    });
}

std::uint32_t Accelerator::add_mesh(std::unique_ptr<TriangleMesh> mesh, const Material* material,
                                    std::vector<const Light*> lights, const FloatTexture* alpha,
                                    const MediumInterface* medium_interface) {
    if (!mesh->finalized()) mesh->finalize();
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh->p.size()));
    for (std::size_t i = 0; i < mesh->p.size(); ++i) {
        v[3 * i] = mesh->p[i].x;
        v[3 * i + 1] = mesh->p[i].y;
        v[3 * i + 2] = mesh->p[i].z;
        (building_ ? building_->bounds : bounds_).extend(mesh->p[i]);
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh->triangle_count()));
    std::copy(mesh->indices.begin(), mesh->indices.end(), idx);
    std::unique_ptr<AlphaCutout> cutout;
    if (alpha) {
        cutout = std::make_unique<AlphaCutout>(AlphaCutout{mesh.get(), alpha});
        rtcSetGeometryUserData(geom, cutout.get());
        rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
        rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
    }
    Record r;
    r.kind = Kind::Mesh;
    r.mesh = std::move(mesh);
    r.material = material;
    r.medium_interface = medium_interface;
    r.lights = std::move(lights);
    r.cutout = std::move(cutout);
    return attach(geom, std::move(r));
}

std::uint32_t Accelerator::add_patches(std::unique_ptr<BilinearPatchMesh> patches, const Material* material,
                                       std::vector<const Light*> lights, const FloatTexture* alpha,
                                       const MediumInterface* medium_interface) {
    if (patches->rectangle.size() != patches->patch_count()) patches->finalize();
    for (Point3f p : patches->p) (building_ ? building_->bounds : bounds_).extend(p);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, unsigned(patches->patch_count()));
    Record r;
    r.kind = Kind::Patches;
    r.patch_geometry = std::make_unique<PatchUserData>(PatchUserData{patches.get(), alpha});
    rtcSetGeometryUserData(geom, r.patch_geometry.get());
    rtcSetGeometryBoundsFunction(geom, patch_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, patch_intersect);
    rtcSetGeometryOccludedFunction(geom, patch_occluded);
    r.patches = std::move(patches);
    r.material = material;
    r.medium_interface = medium_interface;
    r.lights = std::move(lights);
    return attach(geom, std::move(r));
}

std::uint32_t Accelerator::add_shape(std::unique_ptr<AnalyticShape> shape, const Material* material,
                                     const Light* light, bool native_sphere,
                                     const MediumInterface* medium_interface) {
    (building_ ? building_->bounds : bounds_).extend(shape->bounds());
    Record r;
    r.material = material;
    r.medium_interface = medium_interface;
    if (light) r.lights.push_back(light); // one primitive, so at most one area light
    RTCGeometry geom;
    auto* sphere = dynamic_cast<const SphereShape*>(shape.get());
    if (native_sphere && sphere && sphere->is_round()) {
        geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        Point3f c = sphere->center();
        v[0] = c.x;
        v[1] = c.y;
        v[2] = c.z;
        v[3] = sphere->world_radius();
        r.kind = Kind::NativeSphere;
    } else {
        geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geom, 1);
        rtcSetGeometryUserData(geom, shape.get());
        rtcSetGeometryBoundsFunction(geom, shape_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geom, shape_intersect);
        rtcSetGeometryOccludedFunction(geom, shape_occluded);
        r.kind = Kind::Analytic;
    }
    r.shape = std::move(shape);
    return attach(geom, std::move(r));
}

void Accelerator::add_curves(std::unique_ptr<Curves> curves, const Material* material,
                             const MediumInterface* medium_interface, const FloatTexture* alpha) {
    if (curves->segment_count() == 0) return;
    (building_ ? building_->bounds : bounds_).extend(curves->bounds());
    std::vector<PendingCurves>& pending = building_ ? building_->pending_curves : pending_curves_;
    for (PendingCurves& p : pending)
        if (p.material == material && p.medium_interface == medium_interface && p.alpha == alpha &&
            p.curves->type == curves->type && p.curves->flip_normal == curves->flip_normal &&
            p.curves->tessellation == curves->tessellation) {
            p.curves->append(*curves);
            return;
        }
    pending.push_back({std::move(curves), material, medium_interface, alpha});
}

void Accelerator::flush_curves() {
    std::vector<PendingCurves>& pending = building_ ? building_->pending_curves : pending_curves_;
    for (PendingCurves& p : pending) {
        const Curves& c = *p.curves;
        const std::size_t n = c.segment_count();
        RTCGeometry geom = rtcNewGeometry(device_, c.type == CurveType::Ribbon
                                                       ? RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE
                                                       : RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
        rtcSetGeometryTessellationRate(geom, float(c.tessellation));
        // Four control points (x, y, z, radius) per segment; radii r0, (2r0 + r1)/3, (r0 + 2r1)/3, r1 make
        // Embree's Bézier-interpolated radius linear in u, as pbrt-v4's width is.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                              RTC_FORMAT_FLOAT4, 4 * sizeof(float), 4 * n));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), n));
        float* nb = nullptr;
        if (c.type == CurveType::Ribbon)
            nb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_NORMAL, 0,
                                                             RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
        for (std::size_t i = 0; i < n; ++i) {
            idx[i] = unsigned(4 * i);
            float r0 = 0.5f * c.width[i][0], r1 = 0.5f * c.width[i][1];
            for (int k = 0; k < 4; ++k) {
                float* q = v + 4 * (4 * i + std::size_t(k));
                q[0] = c.cp[i][std::size_t(k)].x;
                q[1] = c.cp[i][std::size_t(k)].y;
                q[2] = c.cp[i][std::size_t(k)].z;
                q[3] = r0 + (r1 - r0) * float(k) / 3;
                if (nb) {
                    // The normal's control values linear in u (Embree orients the ribbon by them).
                    Vector3f a(c.normal[i][0]), b(c.normal[i][1]), m = a + (b - a) * (float(k) / 3);
                    float* o = nb + 3 * (4 * i + std::size_t(k));
                    o[0] = m.x;
                    o[1] = m.y;
                    o[2] = m.z;
                }
            }
        }
        Record r;
        if (p.alpha) {
            r.cutout = std::make_unique<AlphaCutout>(AlphaCutout{nullptr, p.alpha, p.curves.get()});
            rtcSetGeometryUserData(geom, r.cutout.get());
            rtcSetGeometryIntersectFilterFunction(geom, curve_alpha_filter);
            rtcSetGeometryOccludedFilterFunction(geom, curve_alpha_filter);
        }
        r.kind = Kind::Curve;
        r.curves = std::move(p.curves);
        r.material = p.material;
        r.medium_interface = p.medium_interface;
        attach(geom, std::move(r));
    }
    pending.clear();
}

void Accelerator::commit() {
    flush_curves();
    // A few analytic shapes in the world are tested by every ray directly, out of Embree: their user-geometry
    // BVH is one leaf that Embree enters for every ray it traces, at the cost of a traversal of its own
    // (docs/performance.md: the fog room's one sphere cost 370 instructions per closest-hit ray, 600 per
    // shadow ray).
    direct_shapes_.clear();
    std::vector<std::uint32_t> analytic;
    for (std::uint32_t id = 0; id < records_.size(); ++id)
        if (records_[id].kind == Kind::Analytic) analytic.push_back(id);
    const bool direct = analytic.size() <= kDirectShapes;
    for (std::uint32_t id : analytic) {
        RTCGeometry g = rtcGetGeometry(scene_, id);
        if (direct)
            rtcDisableGeometry(g);
        else
            rtcEnableGeometry(g); // (disabled by an earlier commit with fewer shapes)
    }
    if (direct) direct_shapes_ = std::move(analytic);
    auto curves = [](const std::vector<Record>& records) {
        return std::any_of(records.begin(), records.end(),
                           [](const Record& r) { return r.kind == Kind::Curve; });
    };
    packets_supported_ = !curves(records_);
    for (const auto& p : prototypes_)
        if (curves(p->records)) packets_supported_ = false;
    rtcCommitScene(scene_);
}

void Accelerator::intersect_direct(RTCRayHit& rh) const {
    for (std::uint32_t id : direct_shapes_)
        record_shape_hit(*records_[id].shape, &rh, id, 0, RTC_INVALID_GEOMETRY_ID);
}

bool Accelerator::direct_crossings(const RTCRay& r, ShadowCrossings* out) const {
    for (std::uint32_t id : direct_shapes_) {
        const Record& rec = records_[id];
        float t[2];
        int n = kept_crossings(*rec.shape, r, id, t);
        for (int i = 0; i < n; ++i) {
            if (!out) return false; // a plain occlusion test: any crossing blocks
            if (!rec.passable) return false;
            if (out->n == kMaxShadowCrossings) {
                out->overflow = true;
                return false;
            }
            RTCRayHit& k = out->hits[out->n++].rh;
            k.ray = r;
            k.ray.tfar = t[i];
            k.hit = RTCHit{};
            k.hit.Ng_z = 1;
            k.hit.primID = 0;
            k.hit.geomID = id;
            k.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        }
    }
    return true;
}

bool Accelerator::intersect(const Ray& ray, SurfaceHit* hit) const {
    Found found;
    return find(ray, &found) && complete(found, ray, hit);
}

bool Accelerator::find(const Ray& ray, Found* found) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit& rh = found->rh;
    rh.ray = to_embree(ray, embree_time(ray.time));
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (!traceable(rh.ray)) return false;
    rtcIntersect1(scene_, &ctx, &rh);
    intersect_direct(rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
}

std::uint32_t Accelerator::find_packet(const Ray* rays, int n, Found* found) const {
    alignas(32) int valid[kPacket] = {};
    alignas(32) RTCRayHit8 p{};
    for (int i = 0; i < n; ++i) {
        const RTCRay r = to_embree(rays[i], embree_time(rays[i].time));
        valid[i] = traceable(r) ? -1 : 0;
        p.ray.org_x[i] = r.org_x, p.ray.org_y[i] = r.org_y, p.ray.org_z[i] = r.org_z;
        p.ray.dir_x[i] = r.dir_x, p.ray.dir_y[i] = r.dir_y, p.ray.dir_z[i] = r.dir_z;
        p.ray.tnear[i] = r.tnear, p.ray.tfar[i] = r.tfar, p.ray.time[i] = r.time;
        p.ray.mask[i] = r.mask, p.ray.id[i] = r.id, p.ray.flags[i] = r.flags;
    }
    for (int i = 0; i < kPacket; ++i) {
        p.hit.geomID[i] = p.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
        p.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, scene_, &ctx, &p);
    std::uint32_t found_bits = 0;
    for (int i = 0; i < n; ++i) {
        RTCRayHit& rh = found[i].rh;
        rh = rtcGetRayHitFromRayHitN(reinterpret_cast<RTCRayHitN*>(&p), kPacket, unsigned(i));
        if (!valid[i]) continue; // find() returns false for an untraceable ray
        intersect_direct(rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) found_bits |= 1u << i;
    }
    return found_bits;
}

bool Accelerator::complete(const Found& found, const Ray& ray, SurfaceHit* hit) const {
    const RTCRayHit& rh = found.rh;
    if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
        fill_hit(records_[rh.hit.geomID], rh, ray, hit);
        return true;
    }
    // A hit inside an instance: fill it in instance space, then carry it to the world.
    const Record& inst = records_[rh.hit.instID[0]];
    Transform moved;
    if (inst.moving) {
        // The transform Embree traversed with at this time, so the hit agrees with its traversal.
        float xfm[12];
        rtcGetGeometryTransform(inst.moving, rh.ray.time, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, xfm);
        Matrix4 m = Matrix4::identity();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) m(r, c) = xfm[4 * r + c];
        auto inv = inverse(m);
        if (!inv) return false; // a scale passing through zero: nothing to see at this instant
        moved = Transform(m, *inv);
    }
    const Transform& w = inst.moving ? moved : inst.world_from_instance;
    Transform instance_from_world = w.inverse();
    Ray local{instance_from_world(ray.o), instance_from_world(ray.d), ray.tmax, ray.time, ray.medium};
    fill_hit(prototypes_[inst.prototype]->records[rh.hit.geomID], rh, local, hit);
    // The point's error bound through the affine map (after PBR 4th ed. §6.8.6): each coordinate gets
    // |M| (γ3 |p| + (1 + γ3) err) + γ3 |translation|.
    const Matrix4& m = w.matrix();
    Vector3f err;
    for (int r = 0; r < 3; ++r) {
        double e = gamma_bound(3) * std::abs(m(r, 3));
        for (int c = 0; c < 3; ++c)
            e += std::abs(m(r, c)) *
                 (gamma_bound(3) * std::abs(hit->p[c]) + (1 + gamma_bound(3)) * hit->p_error[c]);
        err[r] = float(e);
    }
    hit->p = w(hit->p);
    hit->p_error = err;
    hit->n = normalize(w(hit->n));
    hit->ns = normalize(w(hit->ns));
    hit->dpdu = w(hit->dpdu);
    hit->world_from_instance = &w;
    if (inst.moving) {
        // `moved` ends with this call, so the shading partials (which bump mapping asks for later) are taken
        // now; a moving instance's hits are rare enough that every one can pay for them. (A filtered texture
        // there, which needs the partials again for its footprint, reads its finest level.)
        hit->complete_shading_partials();
        hit->partials_source = nullptr;
        hit->world_from_instance = nullptr;
    }
    hit->wo = normalize(-ray.d);
    return true;
}

void Accelerator::fill_hit(const Record& rec, const RTCRayHit& rh, const Ray& ray, SurfaceHit* hit) {
    float t = rh.ray.tfar;
    hit->face_index = 0; // meshes and patches set their own
    switch (rec.kind) {
    case Kind::Mesh:
        rec.mesh->fill_hit(rh.hit.primID, rh.hit.u, rh.hit.v, t, ray, hit);
        break;
    case Kind::NativeSphere:
    case Kind::Analytic:
        rec.shape->fill_hit(t, ray, hit);
        break;
    case Kind::Patches:
        rec.patches->fill_hit(rh.hit.primID, rh.hit.u, rh.hit.v, t, ray, hit);
        break;
    case Kind::Curve:
        rec.curves->fill_hit(rh.hit.primID, rh.hit.u, t, ray, hit);
        break;
    case Kind::Instance:
        break; // never hit itself: Embree reports the instanced geometry
    }
    hit->geom_id = rh.hit.geomID;
    hit->prim_id = rh.hit.primID;
    hit->material = rec.material;
    hit->medium_interface = rec.medium_interface;
    hit->medium = ray.medium;
    hit->world_from_instance = nullptr; // intersect() sets it for a hit in an instance
    hit->time = ray.time;
    hit->area_light =
        rec.lights.empty()
            ? nullptr
            : rec.lights[rec.kind == Kind::Mesh || rec.kind == Kind::Patches ? rh.hit.primID : 0];
}

bool Accelerator::medium_beyond(const Found& found, const Ray& ray, const Medium** beyond) const {
    const RTCRayHit& rh = found.rh;
    const bool instanced = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
    const Record& rec = record_of(rh.hit.geomID, rh.hit.instID[0]);
    if (!rec.medium_interface) {
        *beyond = ray.medium;
        return true;
    }
    const bool moving = instanced && records_[rh.hit.instID[0]].moving;
    if (!moving && (rec.kind == Kind::Mesh || rec.kind == Kind::Analytic || rec.kind == Kind::NativeSphere)) {
        // d · n in the geometry's own space: an instance's hit normal is M^-T n_local, and
        // d · M^-T n_local = M^-1 d · n_local.
        Ray local = ray;
        if (instanced) {
            const Transform instance_from_world = records_[rh.hit.instID[0]].world_from_instance.inverse();
            local.o = instance_from_world(ray.o);
            local.d = instance_from_world(ray.d);
        }
        bool along = rec.kind == Kind::Mesh ? dot(local.d, rec.mesh->geometric_normal(rh.hit.primID)) > 0
                                            : rec.shape->leaves_along_normal(rh.ray.tfar, local);
        *beyond = along ? rec.medium_interface->outside : rec.medium_interface->inside;
        return true;
    }
    SurfaceHit hit;
    if (!complete(found, ray, &hit)) return false;
    *beyond = hit.medium_for(ray.d);
    return true;
}

float Accelerator::intersect_distance(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray = to_embree(ray, embree_time(ray.time));
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    if (!traceable(rh.ray)) return kInfinity;
    rtcIntersect1(scene_, &ctx, &rh);
    intersect_direct(rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
}

namespace {

struct ShadowContext {
    RTCIntersectContext ctx; // first, so Embree's context pointer is this struct's
    const Accelerator* accelerator;
    Accelerator::ShadowCrossings* out;
};

} // namespace

void Accelerator::shadow_filter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    const auto* sc = reinterpret_cast<const ShadowContext*>(args->context);
    const auto* h = reinterpret_cast<const RTCHit*>(args->hit);
    const auto* r = reinterpret_cast<const RTCRay*>(args->ray);
    if (!sc->accelerator->record_of(h->geomID, h->instID[0]).passable) return; // a blocker: accepted
    ShadowCrossings& o = *sc->out;
    // With spatial splits a triangle can sit in two leaves and be reported twice: one crossing.
    for (int i = 0; i < o.n; ++i) {
        const RTCRayHit& k = o.hits[i].rh;
        if (k.hit.geomID == h->geomID && k.hit.primID == h->primID && k.hit.instID[0] == h->instID[0] &&
            k.ray.tfar == r->tfar) {
            args->valid[0] = 0;
            return;
        }
    }
    if (o.n == kMaxShadowCrossings) {
        o.overflow = true; // accepted: the traversal ends, and the caller traces crossing by crossing
        return;
    }
    RTCRayHit& k = o.hits[o.n++].rh;
    k.ray = *r;
    k.hit = *h;
    args->valid[0] = 0; // passes: the traversal goes on
}

bool Accelerator::shadow_crossings(const Ray& ray, ShadowCrossings* out) const {
    out->n = 0;
    out->overflow = false;
    ShadowContext sc;
    rtcInitIntersectContext(&sc.ctx);
    sc.ctx.filter = shadow_filter;
    sc.accelerator = this;
    sc.out = out;
    RTCRay r = to_embree(ray, embree_time(ray.time));
    if (!traceable(r)) return true;
    if (!direct_crossings(r, out)) return false;
    rtcOccluded1(scene_, &sc.ctx, &r);
    if (out->overflow || (r.tfar < 0 && std::isinf(r.tfar))) return false;
    // Nearest first (insertion sort: a handful at most).
    for (int i = 1; i < out->n; ++i)
        for (int j = i; j > 0 && out->hits[j].t() < out->hits[j - 1].t(); --j)
            std::swap(out->hits[j], out->hits[j - 1]);
    return true;
}

bool Accelerator::occluded(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r = to_embree(ray, embree_time(ray.time));
    if (!traceable(r)) return false;
    if (!direct_crossings(r, nullptr)) return true;
    rtcOccluded1(scene_, &ctx, &r);
    return r.tfar < 0 && std::isinf(r.tfar);
}

const TriangleMesh* Accelerator::mesh(std::uint32_t id) const { return records_.at(id).mesh.get(); }
const AnalyticShape* Accelerator::shape(std::uint32_t id) const { return records_.at(id).shape.get(); }

std::size_t Accelerator::triangle_count() const {
    std::size_t n = 0;
    for (auto& r : records_)
        if (r.mesh) n += r.mesh->triangle_count();
    for (auto& p : prototypes_)
        for (auto& r : p->records)
            if (r.mesh) n += r.mesh->triangle_count();
    return n;
}

std::size_t Accelerator::instance_count() const {
    std::size_t n = 0;
    for (auto& r : records_) n += r.kind == Kind::Instance;
    return n;
}

} // namespace illum

// Ray traversal by Embree 3: triangle meshes (Embree triangles), pbrt's analytic shapes (sphere, disk,
// cylinder) as Embree user geometry intersected in object space. The accelerator owns the shapes and knows,
// per geometry, its material and the area light of each primitive.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <embree3/rtcore.h>

#include "illum/geometry/analytic_shape.h"
#include "illum/geometry/bilinear_patch.h"
#include "illum/geometry/curves.h"
#include "illum/geometry/surface_hit.h"
#include "illum/geometry/triangle_mesh.h"
#include "illum/math/animated_transform.h"
#include "illum/texture/texture.h"

namespace illum {

// What Embree's callbacks for a bilinear patch mesh see: the patches and their cut-out (nullptr: opaque).
struct PatchUserData {
    const BilinearPatchMesh* mesh;
    const FloatTexture* alpha;
};

class Accelerator {
public:
    Accelerator();
    ~Accelerator();
    Accelerator(const Accelerator&) = delete;
    Accelerator& operator=(const Accelerator&) = delete;

    // Each add returns the geometry id. `lights` has one entry per primitive (null where it does not
    // emit) or is empty when no primitive emits.
    // alpha (optional): a cut-out; where it is below 1 a hit is kept with probability alpha (pbrt-v4's
    // stochastic alpha test, deterministic per ray and surface crossing), so alpha 0 is a hole.
    // medium_interface (optional): the media the surface separates, recorded on its hits.
    std::uint32_t add_mesh(std::unique_ptr<TriangleMesh> mesh, const Material* material,
                           std::vector<const Light*> lights, const FloatTexture* alpha = nullptr,
                           const MediumInterface* medium_interface = nullptr);
    // Bilinear patches (pbrt-v4's "bilinearmesh") as Embree user geometry, one primitive per patch bounded
    // by its corners' box; `lights` and `alpha` as for add_mesh.
    std::uint32_t add_patches(std::unique_ptr<BilinearPatchMesh> patches, const Material* material,
                              std::vector<const Light*> lights, const FloatTexture* alpha = nullptr,
                              const MediumInterface* medium_interface = nullptr);
    // A sphere, disk or cylinder (its cut-out, if any, is the shape's alpha()) as Embree user geometry.
    // native_sphere: a whole round sphere (SphereShape::is_round()) becomes an Embree sphere point
    // instead. Only bench/shape_bench.cpp asks for it: the user geometry measured faster
    // (docs/performance.md).
    std::uint32_t add_shape(std::unique_ptr<AnalyticShape> shape, const Material* material,
                            const Light* light, bool native_sphere = false,
                            const MediumInterface* medium_interface = nullptr);
    // Curves (pbrt-v4's "curve") as Embree's native Bézier curves: flat and cylinder as ray-facing ribbons,
    // ribbons oriented by their normals (curves.h). All curves of one material, medium interface, alpha,
    // type, orientation and tessellation rate are gathered into one Embree geometry, made at commit() or
    // end_prototype(). alpha as for add_mesh, evaluated at the hit's (u, v) (curves.h).
    void add_curves(std::unique_ptr<Curves> curves, const Material* material,
                    const MediumInterface* medium_interface = nullptr, const FloatTexture* alpha = nullptr);
    // Object instancing (pbrt's ObjectBegin/ObjectInstance): between begin_prototype() and end_prototype()
    // the add_* calls build a prototype (an Embree scene of its own, in instance space); add_instance()
    // places it in the world any number of times at the cost of one Embree instance each.
    std::uint32_t begin_prototype();
    void end_prototype();
    void add_instance(std::uint32_t prototype, const Transform& world_from_instance);
    // Motion blur: the prototype placed by a moving transform, an Embree instance with motion time steps
    // (motion_steps.h). Call set_shutter() first. A moving shape is a prototype of its own placed so, as
    // pbrt-v4 places it (AnimatedPrimitive: the shape in object space, the ray carried there at its time).
    // Returns the instance's id for moving_transform() (kNoInstance when the prototype is empty).
    std::uint32_t add_moving_instance(std::uint32_t prototype, const AnimatedTransform& world_from_instance);
    static constexpr std::uint32_t kNoInstance = ~std::uint32_t(0);
    // The transform a moving instance's hits at this time are carried to the world by (Embree's
    // interpolation of its steps, as complete() uses it), so what is sampled on a moving emitter lies on the
    // surface rays find; nullopt where it is singular (a scale passing through zero).
    std::optional<Transform> moving_transform(std::uint32_t instance, float time) const;
    // The prototype placed by outer(t) · inner(t): a moving shape of an object definition (its own
    // prototype, moved by `inner`) in an object instance (`outer`, still or moving). Embree instances one
    // level deep, so each use of the definition places its moving shapes itself (motion_steps.h).
    void add_moving_instance(std::uint32_t prototype, const AnimatedTransform& outer,
                             const AnimatedTransform& inner);
    // The shutter interval [open, close] that ray times fall in (Embree's time 0..1 spans it).
    void set_shutter(float open, float close);
    void commit();

    // Closest hit along the ray within (0, ray.tmax).
    bool intersect(const Ray& ray, SurfaceHit* hit) const;
    // The same in two steps: the closest hit as Embree finds it, then (complete) its surface data, which a
    // caller may never need (volpath: a collision in the medium often ends the ray's stretch first).
    struct Found {
        RTCRayHit rh;
        float t() const { return rh.ray.tfar; }
    };
    bool find(const Ray& ray, Found* found) const;
    // find() for n <= kPacket rays at once, traced as one coherent Embree packet (rtcIntersect8): bit i of
    // the result is find(rays[i], &found[i]). The camera rays of one pixel's samples cost about a third of
    // their single-ray traversal this way (docs/performance.md). The user-geometry and alpha callbacks take
    // a packet's rays one by one. Only where packets_supported().
    static constexpr int kPacket = 8;
    std::uint32_t find_packet(const Ray* rays, int n, Found* found) const;
    // Whether find_packet() finds exactly what find() does: not in a scene with curves, whose hits Embree's
    // packet intersector computes with other roundings than its single-ray one (set by commit()).
    bool packets_supported() const { return packets_supported_; }
    // The surface data of what find() found for the same ray; false if there is nothing to see after all (an
    // instance whose motion scales it through zero at this time).
    bool complete(const Found& found, const Ray& ray, SurfaceHit* hit) const;
    // The medium on the far side of what find() (or shadow_crossings()) found, for the ray going on along
    // ray.d: what complete() followed by SurfaceHit::medium_for(ray.d) gives, without the rest of the hit's
    // surface data. False where complete() would be (nothing to see).
    bool medium_beyond(const Found& found, const Ray& ray, const Medium** beyond) const;
    // Closest-hit traversal only, without computing the hit's surface data (for measuring Embree's own
    // ray rate); returns the hit distance or infinity.
    float intersect_distance(const Ray& ray) const;
    // Whether anything blocks the ray within (0, ray.tmax).
    bool occluded(const Ray& ray) const;

    // Shadow rays through media: surfaces marked passable (mark_passable: a boundary between media with no
    // material) let them through, anything else blocks them. One occlusion traversal gathers the passable
    // surfaces the ray crosses (at most kMaxShadowCrossings) and stops at the first blocker, where tracing
    // from crossing to crossing would take one closest-hit traversal each. Returns false if blocked; else
    // the crossings, nearest first (complete() gives each one's surface). `overflow`: there were more than
    // fit (the ray is then reported blocked; the caller must trace crossing by crossing instead).
    static constexpr int kMaxShadowCrossings = 8;
    // A world with at most this many analytic shapes (outside object instances) tests them directly, out
    // of Embree (commit()); with three, veach-mis's spheres, the direct tests cost 1% more instructions than
    // Embree's traversal (docs/performance.md).
    static constexpr std::size_t kDirectShapes = 2;
    struct ShadowCrossings {
        int n = 0;
        bool overflow = false;
        Found hits[kMaxShadowCrossings];
    };
    bool shadow_crossings(const Ray& ray, ShadowCrossings* out) const;
    // Whether any geometry is passable (false: a shadow ray is blocked by whatever it meets).
    bool any_passable() const { return any_passable_; }
    // Marks every geometry (in prototypes too) whose material passable(material) says shadow rays pass.
    template <class Passable>
    void mark_passable(Passable&& passable) {
        any_passable_ = false;
        auto mark = [&](Record& r) {
            r.passable = passable(r.material);
            // An instance's own record is never tested (its prototype's records are).
            if (r.passable && r.kind != Kind::Instance) any_passable_ = true;
        };
        for (Record& r : records_) mark(r);
        for (auto& p : prototypes_)
            for (Record& r : p->records) mark(r);
    }

    Bounds3f bounds() const { return bounds_; }
    const TriangleMesh* mesh(std::uint32_t geom_id) const;
    const AnalyticShape* shape(std::uint32_t geom_id) const;
    // Triangles stored (each prototype's once, however often it is instanced) and instances placed.
    std::size_t triangle_count() const;
    std::size_t instance_count() const;
    std::size_t geometry_count() const { return records_.size(); }

private:
    enum class Kind : std::uint8_t { Mesh, NativeSphere, Analytic, Instance, Curve, Patches };
    struct AlphaCutout {
        const TriangleMesh* mesh;
        const FloatTexture* alpha;
        const Curves* curves = nullptr; // for curve_alpha_filter, instead of mesh
    };
    struct Record {
        Kind kind = Kind::Mesh;
        std::unique_ptr<TriangleMesh> mesh;
        std::unique_ptr<BilinearPatchMesh> patches;
        std::unique_ptr<PatchUserData> patch_geometry; // owned here; Embree holds a pointer to it
        std::unique_ptr<AnalyticShape> shape;
        std::unique_ptr<Curves> curves;
        const Material* material = nullptr;
        const MediumInterface* medium_interface = nullptr;
        std::vector<const Light*> lights;
        std::unique_ptr<AlphaCutout> cutout; // owned here; Embree holds a pointer to it
        std::uint32_t prototype = 0;         // Kind::Instance
        Transform world_from_instance;       // Kind::Instance
        RTCGeometry moving = nullptr;        // Kind::Instance with motion: Embree interpolates its transform
        bool passable = false;               // shadow rays pass (mark_passable)
    };
    // Curves gathered for one Embree geometry.
    struct PendingCurves {
        std::unique_ptr<Curves> curves;
        const Material* material = nullptr;
        const MediumInterface* medium_interface = nullptr;
        const FloatTexture* alpha = nullptr;
    };
    struct Prototype {
        RTCScene scene = nullptr;
        std::vector<Record> records;
        Bounds3f bounds;
        std::vector<PendingCurves> pending_curves;
    };
    // The world's analytic shapes when it has at most kDirectShapes of them (commit() disables them in
    // Embree): each ray tests them itself, which costs less than Embree's traversal of their own
    // user-geometry BVH, a single leaf entered by every ray.
    std::vector<std::uint32_t> direct_shapes_;
    // The nearest kept crossing of the direct shapes nearer than rh's hit becomes its hit.
    void intersect_direct(RTCRayHit& rh) const;
    // The direct shapes' kept crossings of r: gathered into `out` where passable (false when one blocks or
    // they overflow it); with out null, false at any crossing (a plain occlusion test).
    bool direct_crossings(const RTCRay& r, ShadowCrossings* out) const;
    // Fills the hit of an Embree hit on the geometry of `rec` along `ray` (in that geometry's space).
    static void fill_hit(const Record& rec, const RTCRayHit& rh, const Ray& ray, SurfaceHit* hit);
    // Embree's ray time: the ray's time as a fraction of the shutter interval.
    float embree_time(float time) const;
    static void alpha_filter(const RTCFilterFunctionNArguments* args);
    static void curve_alpha_filter(const RTCFilterFunctionNArguments* args);
    // The context filter of shadow_crossings(): gathers passable surfaces, accepts blockers.
    static void shadow_filter(const RTCFilterFunctionNArguments* args);
    // The record of a hit's geometry (in the instance's prototype for a hit inside an instance).
    const Record& record_of(std::uint32_t geom_id, std::uint32_t inst_id) const {
        if (inst_id == RTC_INVALID_GEOMETRY_ID) return records_[geom_id];
        return prototypes_[records_[inst_id].prototype]->records[geom_id];
    }
    std::uint32_t attach(RTCGeometry geom, Record record);
    // An Embree instance of the prototype with these motion steps; world_at(t) bounds it along its motion
    // over [t0, t1].
    template <class WorldAt>
    void place_moving(std::uint32_t prototype, const std::vector<TransformComponents>& steps,
                      WorldAt&& world_at, double t0, double t1);
    // Makes the Embree geometries of the curves gathered for the world or the prototype being built.
    void flush_curves();

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<Record> records_;
    bool any_passable_ = true; // until mark_passable() says otherwise
    bool packets_supported_ = false;
    std::vector<std::unique_ptr<Prototype>> prototypes_;
    Prototype* building_ = nullptr;             // the prototype under construction, if any
    std::vector<PendingCurves> pending_curves_; // the world's
    Bounds3f bounds_;
    float shutter_open_ = 0, shutter_close_ = 1, inv_shutter_ = 1;
};

} // namespace illum

// Integrators estimate the value of one camera sample: radiance for the physical ones, a surface
// quantity for the debug passes. They read the scene and write nothing shared; per-thread state
// (sampler, scratch arena, ray counter) comes in a ThreadContext.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "illum/geometry/ray.h"
#include "illum/geometry/ray_differentials.h"
#include "illum/radiometry/quantity.h"
#include "illum/radiometry/sampled_wavelengths.h"
#include "illum/render/sampler.h"
#include "illum/render/scene.h"
#include "illum/util/arena.h"

namespace illum {

struct ThreadContext {
    Sampler sampler;
    ScratchArena arena;
    // The current camera sample's wavelengths (spectral mode) or RGB mode's; a dispersive event terminates
    // the secondary ones.
    SampledWavelengths lambda;
    // The current camera ray's differentials (valid only in scenes with filtered textures, set by the
    // render loop; render/texture_footprint.h).
    RayDifferentials camera_differentials;
    // camera_differentials for an integrator's path: copied only where they are valid, since the render
    // loop has just stored them and a copy of the whole struct would wait for those stores.
    RayDifferentials path_differentials() const {
        RayDifferentials rd;
        if (camera_differentials.valid) [[unlikely]]
            rd = camera_differentials;
        return rd;
    }
    std::uint64_t rays = 0; // rays traced (closest hit and shadow)
    // The current camera ray's closest hit when the render loop traced it in a packet with the pixel's
    // other samples (Accelerator::find_packet): the integrator's first find() or intersect() of that very
    // ray takes it instead of tracing the ray again.
    struct PrimedHit {
        bool pending = false;
        bool hit = false;
        Ray ray;
        Accelerator::Found found;
        bool is_for(const Ray& r) const {
            return r.o == ray.o && r.d == ray.d && r.tmax == ray.tmax && r.time == ray.time;
        }
    } primed;

    explicit ThreadContext(const Sampler& s) : sampler(s) {}
};

class Integrator {
public:
    explicit Integrator(const Scene& scene) : scene_(scene) {}
    virtual ~Integrator() = default;
    // The value the film records for this camera ray: the radiance [W m^-2 sr^-1] arriving along it for the
    // physical integrators (a debug pass stores its own value in the radiance channels, aov_integrator.h).
    virtual Radiance3 estimate(const Ray& camera_ray, ThreadContext& tc) const = 0;
    // Whether estimates may be negative (a signed debug pass); radiance never is, so a negative radiance
    // estimate is a numerical failure that the render loop drops and counts.
    virtual bool signed_values() const { return false; }
    // Whether the estimate's first query is the camera ray's closest hit (find() or intersect() of the ray
    // estimate() is given), so that the render loop may trace the camera rays of a pixel's samples as one
    // packet and hand each its hit (ThreadContext::primed).
    virtual bool starts_at_camera_hit() const { return false; }
    // Whether the estimate is radiance, which spectral mode computes at sampled wavelengths; a debug pass's
    // value is RGB in either mode.
    virtual bool radiometric() const { return true; }

protected:
    // Accelerator::intersect's two steps, so that a primed hit serves either query.
    bool intersect(const Ray& ray, SurfaceHit* hit, ThreadContext& tc) const {
        Accelerator::Found found;
        return find(ray, &found, tc) && scene_.accelerator.complete(found, ray, hit);
    }
    bool find(const Ray& ray, Accelerator::Found* found, ThreadContext& tc) const {
        ++tc.rays;
        if (tc.primed.pending && tc.primed.is_for(ray)) [[unlikely]] {
            tc.primed.pending = false;
            *found = tc.primed.found;
            return tc.primed.hit;
        }
        return scene_.find(ray, found);
    }
    bool occluded(const Ray& ray, ThreadContext& tc) const {
        ++tc.rays;
        return scene_.occluded(ray);
    }
    // Whether the light sample ls is visible from hit.
    bool unoccluded(const SurfaceHit& hit, const struct LightLiSample& ls, ThreadContext& tc) const;

    const Scene& scene_;
};

// The names make_integrator knows (scene files and --integrator may use each).
const std::vector<std::string>& integrator_names();
// Integrator by name: "path", "direct", "albedo", "normal". Throws illum::Error for another name.
std::unique_ptr<Integrator> make_integrator(const std::string& name, const Scene& scene, int max_depth);

} // namespace illum

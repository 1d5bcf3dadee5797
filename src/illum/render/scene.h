// The runtime scene: Embree geometry, lights, materials, camera and film settings, built once from a
// SceneDesc. The render loop only reads it.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "illum/bsdf/material.h"
#include "illum/camera/camera.h"
#include "illum/camera/camera_motion.h"
#include "illum/camera/film.h"
#include "illum/camera/filter.h"
#include "illum/camera/sensor.h"
#include "illum/geometry/accelerator.h"
#include "illum/light/direct_light_sampler.h"
#include "illum/light/light.h"
#include "illum/light/light_sampler.h"
#include "illum/medium/medium.h"
#include "illum/render/sampler.h"
#include "illum/texture/texture.h"
#include "illum/util/diagnostics.h"
#include "illum/util/error.h"

namespace illum {

// What the scene file asks of the render; the command line may override each.
struct RenderRequest {
    std::string integrator = "path";
    int max_depth = 5;
    // The integrator's "lightsampler" (pbrt-v4's default "bvh"; direct_light_sampler.h).
    LightSamplerKind light_sampler = LightSamplerKind::bvh;
    std::string sampler = "sobol";
    int spp = 16;
    SamplerSettings sampler_settings;     // the Sampler directive's parameters (sampler.h)
    std::optional<uint64_t> sampler_seed; // its "seed", if given
    std::string output;                   // the film's filename, "" when none
    bool save_fp16 = true;                // the film's "savefp16": EXR output in half precision
    // Option directives (scene_options.h).
    std::optional<std::uint64_t> seed;
    bool disable_pixel_jitter = false;
    bool disable_texture_filtering = false; // pbrt-v4's Option: every footprint is zero
    bool disable_wavelength_jitter = false;
    bool force_diffuse = false;
    float displacement_edge_scale = 1; // scales plymesh's "edgelength" (displacement)
    // The sample sequences' seed: the Sampler's "seed", else Option "seed", else 0 (pbrt-v4's samplers take
    // the Option as their seed's default).
    std::uint64_t scene_seed() const { return sampler_seed ? *sampler_seed : seed.value_or(0); }
    // Integrator "sppm" (pbrt-v4's parameters): photons per iteration (-1: the pixel count), the initial
    // search radius [world units] and the photon streams' seed.
    long long sppm_photons_per_iteration = -1;
    float sppm_radius = 1;
    int sppm_seed = 6502;
    // Integrator "bdpt": pbrt-v4's debug outputs, an image per strategy (s, t) of its unweighted
    // contribution (visualizestrategies) or its MIS-weighted one (visualizeweights, which wins if both).
    bool bdpt_visualize_strategies = false;
    bool bdpt_visualize_weights = false;
    // Integrator "vcm" (vcm_integrator.h): light subpaths per iteration (-1: the pixel count), the initial
    // merging radius (<= 0: from the scene's size), the radius exponent α, the techniques ("vcm", "vc",
    // "vm") and the heuristic (power or balance).
    long long vcm_light_paths = -1;
    float vcm_radius = -1;
    float vcm_alpha = 0.75f;
    std::string vcm_mode = "vcm";
    bool vcm_power_heuristic = false;
};

class Scene {
public:
    Accelerator accelerator;
    std::vector<std::unique_ptr<Light>> lights;
    std::vector<const Light*> infinite_lights;
    // Picks lights without a receiver: photons, light subpaths, and the bidirectional methods' densities.
    PowerLightSampler light_sampler;
    // Picks the light of next-event estimation for a receiver (the request's "lightsampler").
    DirectLightSampler direct_light_sampler;
    std::unique_ptr<Camera> camera;
    std::unique_ptr<Filter> filter;
    // The film's sensor and output colour space, which is also the space RGB inputs are given in
    // (pbrt-v4's ColorSpace; one per scene here).
    Sensor sensor;
    const RGBColorSpace* color_space = &RGBColorSpace::srgb();
    int width = 0, height = 0; // the film's full resolution, onto which the camera projects
    // The pixels the output keeps (the film's cropwindow or pixelbounds; every pixel by default).
    PixelBounds pixel_bounds;
    // The Camera directive's position and type, for errors of integrators that cannot use the camera.
    SourceLocation camera_loc;
    std::string camera_type;
    // The medium the camera sits in (pbrt-v4: the outside medium current at the Camera directive).
    const Medium* camera_medium = nullptr;
    RenderRequest request;
    std::vector<std::string> warnings;
    std::vector<UnsupportedUse> unsupported; // every unsupported feature used, with its position

    // Motion blur: the shutter interval (the camera's "shutteropen", "shutterclose"), whether anything
    // moves (the camera or some geometry; only then does a camera sample draw a time, so a still scene
    // renders as it did without motion blur) and the camera's motion.
    float shutter_open = 0, shutter_close = 1;
    bool has_motion = false;
    CameraMotion camera_motion;
    // Whether some material filters its textures over the footprint (Material::needs_texture_differentials):
    // only then do camera rays carry differentials (render/texture_footprint.h).
    bool texture_filtering = false;
    // The time of a sample, u uniform in [0, 1): pbrt-v4's CameraBase::SampleTime, lerp(u, open, close).
    float sample_time(float u) const { return (1 - u) * shutter_open + u * shutter_close; }
    // A camera ray at the time `time`: where the (moving) camera is then, carrying that time.
    Ray camera_ray_at(const Ray& r, float time) const {
        Ray moved = camera_motion.at(r, time);
        moved.time = time;
        return moved;
    }

    // The camera's importance for a path at `time` (a ray's own time for pdf_we), where a moving camera is
    // then (CameraMotion::sample_wi); a static camera answers directly.
    std::optional<CameraWiSample> camera_sample_wi(Point3f p_ref, Point2f u, float time) const {
        return has_motion ? camera_motion.sample_wi(*camera, p_ref, u, time) : camera->sample_wi(p_ref, u);
    }
    CameraRayPdf camera_pdf_we(const Ray& ray) const {
        return has_motion ? camera_motion.pdf_we(*camera, ray) : camera->pdf_we(ray);
    }

    // Storage that the above points into.
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<std::unique_ptr<ColorTexture>> color_textures;
    std::vector<std::unique_ptr<FloatTexture>> float_textures;
    std::vector<std::unique_ptr<AreaShape>> light_shapes;
    // A moving emitter's geometry at its start pose, which its lights sample (moving_area_light.h).
    std::vector<std::unique_ptr<TriangleMesh>> light_meshes;
    std::vector<std::unique_ptr<BilinearPatchMesh>> light_patches;
    std::vector<std::unique_ptr<Medium>> media;
    std::deque<MediumInterface> medium_interfaces; // stable addresses: hits point at them

    // What `illum info` reports of each medium: its name, type, the memory its data takes and the shapes
    // whose MediumInterface names it (by their source positions).
    struct MediumReport {
        std::string name, type;
        std::size_t bytes = 0;
        std::vector<std::string> bounded_by;
    };
    std::vector<MediumReport> medium_reports;

    // The pixel filter's sample for a camera sample, or (Option "disablepixeljitter") the pixel's centre
    // with weight 1; u is drawn either way.
    FilterSample pixel_filter_sample(Point2f u) const {
        FilterSample fs = filter->sample(u);
        return request.disable_pixel_jitter ? FilterSample{{0, 0}, 1} : fs;
    }
    // The sample of a path's wavelengths, or 1/2 (Option "disablewavelengthjitter").
    float wavelength_sample(float u) const { return request.disable_wavelength_jitter ? 0.5f : u; }
    // A camera or light path's wavelengths: in spectral mode sampled over the visible range from the
    // sampler's next dimension, in RGB mode the fixed set (drawing nothing).
    SampledWavelengths sample_wavelengths(bool spectral, Sampler& sampler) const {
        return spectral ? SampledWavelengths::sample_visible(wavelength_sample(sampler.get_1d()), color_space)
                        : SampledWavelengths::rgb_mode();
    }

    // pixel_bounds, or every pixel when none were set (a scene made by hand).
    PixelBounds output_bounds() const {
        return pixel_bounds.empty() ? PixelBounds::full(width, height) : pixel_bounds;
    }

    bool intersect(const Ray& ray, SurfaceHit* hit) const { return accelerator.intersect(ray, hit); }
    bool find(const Ray& ray, Accelerator::Found* found) const { return accelerator.find(ray, found); }
    bool complete(const Accelerator::Found& found, const Ray& ray, SurfaceHit* hit) const {
        return accelerator.complete(found, ray, hit);
    }
    bool occluded(const Ray& ray) const { return accelerator.occluded(ray); }

    // Registers the lights with the light sampler and lets them see the scene bounds; call once after
    // all geometry and lights are added.
    void finalize();
    // Rebuilds the next-event light sampler as `kind` (the request's light_sampler), after finalize().
    void set_light_sampler(LightSamplerKind kind);
};

} // namespace illum

// The runtime scene: Embree geometry, lights, materials, camera and film settings, built once from a
// SceneDesc. The render loop only reads it.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "illum/bsdf/material.h"
#include "illum/camera/camera.h"
#include "illum/camera/filter.h"
#include "illum/camera/sensor.h"
#include "illum/geometry/accelerator.h"
#include "illum/light/light.h"
#include "illum/light/light_sampler.h"
#include "illum/medium/medium.h"
#include "illum/texture/texture.h"

namespace illum {

// What the scene file asks of the render; the command line may override each.
struct RenderRequest {
    std::string integrator = "path";
    int max_depth = 5;
    std::string sampler = "sobol";
    int spp = 16;
    std::string output; // the film's filename, "" when none
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
    PowerLightSampler light_sampler;
    std::unique_ptr<Camera> camera;
    std::unique_ptr<Filter> filter;
    // The film's sensor and output colour space, which is also the space RGB inputs are given in
    // (pbrt-v4's ColorSpace; one per scene here).
    Sensor sensor;
    const RGBColorSpace* color_space = &RGBColorSpace::srgb();
    int width = 0, height = 0;
    // The medium the camera sits in (pbrt-v4: the outside medium current at the Camera directive).
    const Medium* camera_medium = nullptr;
    RenderRequest request;
    std::vector<std::string> warnings;

    // Storage that the above points into.
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<std::unique_ptr<ColorTexture>> color_textures;
    std::vector<std::unique_ptr<FloatTexture>> float_textures;
    std::vector<std::unique_ptr<AreaShape>> light_shapes;
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

    bool intersect(const Ray& ray, SurfaceHit* hit) const { return accelerator.intersect(ray, hit); }
    bool occluded(const Ray& ray) const { return accelerator.occluded(ray); }

    // Registers the lights with the light sampler and lets them see the scene bounds; call once after
    // all geometry and lights are added.
    void finalize();
};

} // namespace illum

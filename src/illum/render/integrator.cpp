#include "illum/render/integrator.h"

#include <algorithm>

#include "illum/light/light.h"
#include "illum/render/aov_integrator.h"
#include "illum/render/bdpt_integrator.h"
#include "illum/render/direct_integrator.h"
#include "illum/render/lightpath_integrator.h"
#include "illum/render/path_integrator.h"
#include "illum/render/sppm_integrator.h"
#include "illum/render/vcm_integrator.h"
#include "illum/render/volpath_caustics.h"
#include "illum/render/volpath_integrator.h"
#include "illum/util/error.h"

namespace illum {

bool Integrator::unoccluded(const SurfaceHit& hit, const LightLiSample& ls, ThreadContext& tc) const {
    Ray shadow = ls.at_infinity
                     ? hit.spawn_ray(ls.wi)
                     : (ls.n_light == Normal3f{} ? hit.spawn_ray_to(ls.p_light)
                                                 : spawn_ray_to(hit.p, hit.p_error, hit.n, ls.p_light,
                                                                ls.p_light_error, ls.n_light));
    shadow.time = hit.time;
    return !occluded(shadow, tc);
}

// Adding an integrator: its file, and one line here and in integrator_names().
const std::vector<std::string>& integrator_names() {
    static const std::vector<std::string> names = {"path",      "volpath", "direct", "albedo", "normal",
                                                   "lightpath", "sppm",    "bdpt",   "vcm"};
    return names;
}

std::unique_ptr<Integrator> make_integrator(const std::string& name, const Scene& scene, int max_depth) {
    if (name == "path") return std::make_unique<PathIntegrator>(scene, max_depth);
    if (name == "volpath") {
        // Without media volpath's transport is the path tracer's, which is faster on surfaces alone.
        if (!VolPathIntegrator::needed(scene)) return std::make_unique<PathIntegrator>(scene, max_depth);
        // Caustics by light tracing where the camera has an importance function to connect to and some
        // material may scatter specularly (else there are no caustics; a light seen directly is the camera
        // rays' alone then).
        bool specular = std::any_of(scene.materials.begin(), scene.materials.end(),
                                    [](const std::unique_ptr<Material>& m) { return m->may_be_specular; });
        if (specular && scene.camera && scene.camera->has_importance())
            return std::make_unique<VolPathCausticsIntegrator>(scene, max_depth);
        return std::make_unique<VolPathIntegrator>(scene, max_depth);
    }
    if (name == "direct") return std::make_unique<DirectIntegrator>(scene, max_depth);
    if (name == "albedo") return std::make_unique<AovIntegrator>(scene, AovIntegrator::Pass::Albedo);
    if (name == "normal") return std::make_unique<AovIntegrator>(scene, AovIntegrator::Pass::Normal);
    if (name == "lightpath") return std::make_unique<LightPathIntegrator>(scene, max_depth);
    if (name == "bdpt") return std::make_unique<BDPTIntegrator>(scene, max_depth);
    if (name == "sppm") {
        const RenderRequest& r = scene.request;
        return std::make_unique<SPPMIntegrator>(
            scene,
            SppmSettings{max_depth, r.sppm_photons_per_iteration, r.sppm_radius, std::uint64_t(r.sppm_seed)});
    }
    if (name == "vcm") {
        const RenderRequest& r = scene.request;
        VcmSettings v{max_depth,   r.vcm_light_paths,      r.vcm_radius,
                      r.vcm_alpha, VcmSettings::Mode::VCM, r.vcm_power_heuristic};
        if (!parse_vcm_mode(r.vcm_mode, &v.mode)) throw Error("vcm mode must be \"vcm\", \"vc\" or \"vm\"");
        return std::make_unique<VCMIntegrator>(scene, v);
    }
    throw Error("unknown integrator \"" + name +
                "\" (use path, volpath, direct, albedo, normal, lightpath, sppm, bdpt or vcm)");
}

} // namespace illum

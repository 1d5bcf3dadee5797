#include "illum/render/create_render_request.h"

#include <algorithm>
#include <fmt/format.h>

#include "illum/render/integrator.h"
#include "illum/render/vcm_integrator.h"

namespace illum {

RenderRequest create_render_request(const EntityDesc& in, const EntityDesc& s, Diagnostics& diag) {
    RenderRequest r;
    r.max_depth = in.params.get_int("maxdepth", 5);
    if (r.max_depth < -1) throw Error(in.loc, "maxdepth must be -1 (unbounded) or non-negative");
    const std::string& t = in.type;
    const auto& ours = integrator_names();
    if (std::find(ours.begin(), ours.end(), t) != ours.end()) {
        r.integrator = t;
    } else if (t == "simplepath") {
        r.integrator = "path";
    } else if (t == "directlighting") {
        r.integrator = "direct"; // pbrt-v3's name for it
    } else if (t == "mlt" || t == "randomwalk" || t == "simplevolpath" || t == "ambientocclusion" ||
               t == "aov") {
        diag.unsupported(in.loc, fmt::format("integrator \"{}\" is rendered with \"path\"", t));
        r.integrator = "path";
        for (const Param& p : in.params.params()) p.used = true; // its own parameters are not ours to judge
    } else {
        throw Error(in.loc, fmt::format("unknown integrator \"{}\"", t));
    }
    if (r.integrator == "sppm") {
        r.sppm_photons_per_iteration = in.params.get_int("photonsperiteration", -1);
        if (r.sppm_photons_per_iteration == 0 || r.sppm_photons_per_iteration < -1)
            throw Error(in.loc, "photonsperiteration must be positive or -1 (the pixel count)");
        r.sppm_radius = in.params.get_float("radius", 1);
        if (!(r.sppm_radius > 0)) throw Error(in.loc, "radius must be positive");
        r.sppm_seed = in.params.get_int("seed", 6502);
    }
    if (r.integrator == "vcm") {
        // pbrt-v4 has no vcm: the names follow its sppm and bdpt (vcm_integrator.h).
        r.vcm_light_paths = in.params.get_int("photonsperiteration", -1);
        if (r.vcm_light_paths == 0 || r.vcm_light_paths < -1)
            throw Error(in.params.find("photonsperiteration")->loc,
                        "photonsperiteration must be positive or -1 (the pixel count)");
        r.vcm_radius = in.params.get_float("radius", -1);
        if (in.params.find("radius") && !(r.vcm_radius > 0))
            throw Error(in.params.find("radius")->loc, "radius must be positive");
        r.vcm_alpha = in.params.get_float("alpha", 0.75f);
        if (!(r.vcm_alpha > 0 && r.vcm_alpha <= 1))
            throw Error(in.params.find("alpha")->loc, "alpha must be in (0, 1]");
        r.vcm_mode = in.params.get_string("mode", "vcm");
        VcmSettings::Mode mode;
        if (!parse_vcm_mode(r.vcm_mode, &mode))
            throw Error(in.params.find("mode")->loc, "mode must be \"vcm\", \"vc\" or \"vm\"");
        std::string heuristic = in.params.get_string("misheuristic", "balance");
        if (heuristic != "balance" && heuristic != "power")
            throw Error(in.params.find("misheuristic")->loc, "misheuristic must be \"balance\" or \"power\"");
        r.vcm_power_heuristic = heuristic == "power";
    }
    if (r.integrator == "bdpt") {
        r.bdpt_visualize_strategies = in.params.get_bool("visualizestrategies", false);
        r.bdpt_visualize_weights = in.params.get_bool("visualizeweights", false);
    }
    if (in.params.get_bool("regularize", false))
        diag.unsupported(in.params.find("regularize")->loc,
                         "\"regularize\" is not supported; rendered without");
    if (const Param* ls = in.params.find("lightsampler")) {
        std::string name = in.params.get_string("lightsampler", "bvh");
        if (name != "power")
            diag.unsupported(ls->loc, fmt::format("light sampler \"{}\" is replaced by \"power\"", name));
    }

    r.spp = s.params.get_int("pixelsamples", 16);
    if (r.spp <= 0) throw Error(s.loc, "pixelsamples must be positive");
    if (s.type == "independent")
        r.sampler = "independent";
    else if (s.type == "sobol" || s.type == "zsobol" || s.type == "paddedsobol")
        r.sampler = "sobol";
    else if (s.type == "halton" || s.type == "pmj02bn" || s.type == "stratified") {
        diag.unsupported(s.loc, fmt::format("sampler \"{}\" is replaced by \"sobol\"", s.type));
        r.sampler = "sobol";
    } else {
        throw Error(s.loc, fmt::format("unknown sampler \"{}\"", s.type));
    }
    return r;
}

} // namespace illum

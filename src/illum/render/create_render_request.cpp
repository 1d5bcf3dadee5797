#include "illum/render/create_render_request.h"

#include <algorithm>
#include <fmt/format.h>

#include "illum/render/integrator.h"
#include "illum/render/sampler.h"
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
        std::optional<LightSamplerKind> kind = parse_light_sampler(name);
        if (!kind)
            throw Error(
                ls->loc,
                fmt::format("unknown light sampler \"{}\" (uniform, power, bvh or exhaustive)", name));
        r.light_sampler = *kind;
    }

    std::optional<SamplerKind> kind = parse_sampler_kind(s.type);
    if (!kind || s.type == "random" || s.type == "owen-sobol")
        throw Error(s.loc, fmt::format("unknown sampler \"{}\"", s.type));
    r.sampler = s.type;
    // No Sampler directive (SceneDesc's default, pbrt-v4's zsobol, has no position): illum renders with
    // its own padded Sobol, which is as accurate and cheaper (docs/scenes.md, "Samplers").
    if (s.loc.line == 0 && s.loc.file.empty() && s.type == "zsobol") r.sampler = "sobol";
    if (*kind != SamplerKind::stratified) {
        r.spp = s.params.get_int("pixelsamples", 16);
        if (r.spp <= 0) throw Error(s.loc, "pixelsamples must be positive");
    }
    if (s.params.has("seed")) r.sampler_seed = uint64_t(int64_t(s.params.get_int("seed", 0)));
    if (*kind == SamplerKind::zsobol || *kind == SamplerKind::paddedsobol || *kind == SamplerKind::halton) {
        if (const Param* p = s.params.find("randomization")) {
            std::string name = s.params.get_string("randomization", "");
            std::optional<Randomization> rz = parse_randomization(name);
            if (!rz)
                throw Error(
                    p->loc,
                    fmt::format("unknown randomization \"{}\" (none, permutedigits, fastowen or owen)",
                                name));
            if (*kind == SamplerKind::halton && *rz == Randomization::fast_owen)
                throw Error(
                    p->loc,
                    "the halton sampler has no \"fastowen\" randomization (permutedigits, owen or none)");
            r.sampler_settings.randomization = rz;
        }
    }
    if (*kind == SamplerKind::stratified) {
        // pbrt-v4: spp = xsamples x ysamples; "pixelsamples" is not read.
        r.sampler_settings.jitter = s.params.get_bool("jitter", true);
        r.sampler_settings.x_samples = s.params.get_int("xsamples", 4);
        r.sampler_settings.y_samples = s.params.get_int("ysamples", 4);
        if (r.sampler_settings.x_samples <= 0 || r.sampler_settings.y_samples <= 0)
            throw Error(s.loc, "xsamples and ysamples must be positive");
        r.spp = r.sampler_settings.x_samples * r.sampler_settings.y_samples;
    }
    if (*kind == SamplerKind::pmj02bn && r.spp > 65536)
        throw Error(s.loc, "the pmj02bn sampler takes at most 65536 pixel samples");
    return r;
}

} // namespace illum

#include "illum/light/area_emission.h"

#include <fmt/format.h>

#include "illum/param/spectrum_param.h"

namespace illum {

Radiance3 AreaEmission::for_area(float area) const {
    Color3 l = radiance;
    if (power > 0 && area > 0) l *= power / (kPi * (two_sided ? 2.0f : 1.0f) * area);
    return Radiance3(l);
}

AreaEmission create_area_emission(const EntityDesc& a, Diagnostics& diag) {
    if (a.type != "diffuse") throw Error(a.loc, fmt::format("unknown area light type \"{}\"", a.type));
    Color3 l(1.0f);
    if (const Param* p = a.params.find("L")) {
        if (p->type == ParamType::RGB)
            l = *a.params.get_rgb("L");
        else if (p->type == ParamType::Spectrum)
            l = spectrum_param_rgb(*p, SpectrumKind::Illuminant);
        else if (p->type == ParamType::Float)
            l = Color3(a.params.get_float("L", 1));
        else
            a.params.fail(*p, fmt::format("parameter \"L\" cannot be of type {}", to_string(p->type)));
    }
    if (const Param* f = a.params.find("filename")) {
        f->used = true;
        diag.unsupported(f->loc, "an image-textured area light is rendered with its L");
    }
    l *= a.params.get_float("scale", 1);
    if (l.has_negative() || !l.is_finite())
        throw Error(a.loc, "area light radiance must be finite and non-negative");
    return {l, a.params.get_bool("twosided", false), a.params.get_float("power", -1)};
}

} // namespace illum

#include "illum/light/area_emission.h"

#include <fmt/format.h>

#include "illum/param/spectrum_param.h"

namespace illum {

Emission AreaEmission::for_area(float area) const {
    Emission l = radiance;
    if (power > 0 && area > 0) l *= power / (kPi * (two_sided ? 2.0f : 1.0f) * area);
    return l;
}

AreaEmission create_area_emission(const EntityDesc& a, Diagnostics& diag) {
    if (a.type != "diffuse") throw Error(a.loc, fmt::format("unknown area light type \"{}\"", a.type));
    Emission l(Color3(1.0f));
    if (const Param* p = a.params.find("L")) {
        if (p->type == ParamType::RGB)
            l = Emission(*a.params.get_rgb("L"));
        else if (p->type == ParamType::Spectrum) {
            SpectrumParam s = spectrum_param(*p, SpectrumKind::Illuminant);
            l = Emission(s.rgb, std::move(s.spectrum));
        } else if (p->type == ParamType::Float)
            l = Emission(Color3(a.params.get_float("L", 1)));
        else
            a.params.fail(*p, fmt::format("parameter \"L\" cannot be of type {}", to_string(p->type)));
    }
    if (const Param* f = a.params.find("filename")) {
        f->used = true;
        diag.unsupported(f->loc, "an image-textured area light is rendered with its L");
    }
    l *= a.params.get_float("scale", 1);
    if (l.rgb.has_negative() || !l.rgb.is_finite())
        throw Error(a.loc, "area light radiance must be finite and non-negative");
    return {l, a.params.get_bool("twosided", false), a.params.get_float("power", -1)};
}

} // namespace illum

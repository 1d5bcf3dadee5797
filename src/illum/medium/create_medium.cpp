#include "illum/medium/create_medium.h"

#include <cmath>
#include <fmt/format.h>

#include "illum/medium/homogeneous_medium.h"
#include "illum/medium/measured_media.h"
#include "illum/param/spectrum_param.h"

namespace illum {

namespace {

void check_coefficient(const MediumDesc& desc, const Param& p, Color3 c) {
    for (float v : {c.r, c.g, c.b})
        if (!std::isfinite(v) || v < 0)
            desc.params.fail(
                p, fmt::format("medium \"{}\": \"{}\" must be finite and non-negative", desc.name, p.name));
}

} // namespace

MediumSpectrum medium_coefficient(const MediumDesc& desc, const std::string& name, Color3 def) {
    const Param* p = desc.params.find(name);
    if (!p) return MediumSpectrum(def);
    if (p->type == ParamType::RGB) {
        Color3 c = *desc.params.get_rgb(name);
        check_coefficient(desc, *p, c);
        return MediumSpectrum(c);
    }
    if (p->type != ParamType::Spectrum)
        desc.params.fail(*p, fmt::format("parameter \"{}\" has type {}, expected rgb, spectrum or blackbody",
                                         name, to_string(p->type)));
    SpectrumParam s = spectrum_param(*p, SpectrumKind::Unbounded);
    check_coefficient(desc, *p, s.rgb);
    return MediumSpectrum(s.rgb, std::move(s.spectrum));
}

Emission medium_le(const MediumDesc& desc, bool* nonzero) {
    const Param* p = desc.params.find("Le");
    *nonzero = false;
    if (!p) return Emission(Color3(0.0f));
    Emission e;
    if (p->type == ParamType::RGB) {
        Color3 c = *desc.params.get_rgb("Le");
        check_coefficient(desc, *p, c);
        e = Emission(c);
    } else if (p->type == ParamType::Spectrum) {
        SpectrumParam s = spectrum_param(*p, SpectrumKind::Illuminant);
        check_coefficient(desc, *p, s.rgb);
        e = Emission(s.rgb, std::move(s.spectrum));
    } else {
        desc.params.fail(*p, fmt::format("parameter \"Le\" has type {}, expected rgb, spectrum or blackbody",
                                         to_string(p->type)));
    }
    *nonzero = e.rgb.max_component() > 0;
    return e;
}

Emission medium_emission(const MediumDesc& desc, bool* emissive) {
    float scale = desc.params.get_float("Lescale", 1);
    bool nonzero = false;
    Emission e = medium_le(desc, &nonzero);
    if (!(scale >= 0)) desc.params.fail(*desc.params.find("Lescale"), "\"Lescale\" must be non-negative");
    e *= scale;
    *emissive = scale > 0 && nonzero;
    return e;
}

void medium_scattering(const MediumDesc& desc, MediumSpectrum* sigma_a, MediumSpectrum* sigma_s) {
    std::string preset = desc.params.get_string("preset", "");
    if (!preset.empty()) {
        std::optional<MeasuredMedium> m = measured_medium(preset);
        if (!m)
            desc.params.fail(*desc.params.find("preset"),
                             fmt::format("medium \"{}\": unknown preset \"{}\"", desc.name, preset));
        *sigma_a = MediumSpectrum(m->sigma_a);
        *sigma_s = MediumSpectrum(m->sigma_s);
    } else {
        *sigma_a = medium_coefficient(desc, "sigma_a", Color3(1.0f));
        *sigma_s = medium_coefficient(desc, "sigma_s", Color3(1.0f));
    }
    float scale = desc.params.get_float("scale", 1);
    if (!(scale >= 0)) desc.params.fail(*desc.params.find("scale"), "\"scale\" must be non-negative");
    *sigma_a *= scale;
    *sigma_s *= scale;
}

float medium_g(const MediumDesc& desc) {
    float g = desc.params.get_float("g", 0);
    if (!(g > -1 && g < 1)) desc.params.fail(*desc.params.find("g"), "\"g\" must lie in (-1, 1)");
    return g;
}

CreatedMedium create_medium(const MediumDesc& desc, Diagnostics& diag) {
    if (desc.type == "homogeneous") {
        MediumSpectrum sigma_a, sigma_s;
        medium_scattering(desc, &sigma_a, &sigma_s);
        bool emissive = false;
        Emission le = medium_emission(desc, &emissive);
        float g = medium_g(desc);
        return {std::make_unique<HomogeneousMedium>(sigma_a, sigma_s, g, le, emissive),
                {"homogeneous", sizeof(HomogeneousMedium)}};
    }
    CreatedMedium grid = create_grid_medium(desc, diag);
    if (!grid.medium)
        throw Error(desc.loc, fmt::format("medium \"{}\": unknown type \"{}\" (homogeneous, uniformgrid, "
                                          "rgbgrid, cloud or nanovdb)",
                                          desc.name, desc.type));
    return grid;
}

} // namespace illum

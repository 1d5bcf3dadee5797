#include "illum/light/area_emission.h"

#include <fmt/format.h>

#include "illum/light/light_image.h"
#include "illum/param/spectrum_param.h"

namespace illum {

Emission AreaEmission::for_area(float area) const {
    Emission l = radiance;
    float k = kPi * (two_sided ? 2.0f : 1.0f) * area;
    if (image) k *= float(image_mean_luminance);
    if (power > 0 && k > 0) l *= power / k;
    return l;
}

std::unique_ptr<DiffuseAreaLight> AreaEmission::make_light(const AreaShape* shape, float area) const {
    if (image) return std::make_unique<DiffuseAreaLight>(shape, image, for_area(area).rgb.r, two_sided);
    return std::make_unique<DiffuseAreaLight>(shape, for_area(area), two_sided);
}

AreaEmission create_area_emission(const EntityDesc& a, Diagnostics& diag) {
    if (a.type != "diffuse") throw Error(a.loc, fmt::format("unknown area light type \"{}\"", a.type));
    Emission l(Color3(1.0f));
    const Param* p = a.params.find("L");
    if (p) {
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
    AreaEmission e;
    if (a.params.find("filename")) {
        // pbrt-v4: "Both \"L\" and \"filename\" specified for DiffuseAreaLight."
        if (p) throw Error(p->loc, "area light: \"L\" and \"filename\" cannot both be given");
        if (std::optional<Image> img = read_light_image(a, "area light", diag)) {
            double lum = 0;
            for (std::size_t k = 0; k < img->pixel_count(); ++k) lum += img->data()[k].luminance();
            e.image_mean_luminance = lum / double(img->pixel_count());
            e.image = std::make_shared<const Image>(std::move(*img));
        } else {
            l = Emission(Color3(0.0f)); // the missing file is reported when the build ends
        }
    }
    l *= a.params.get_float("scale", 1);
    if (l.rgb.has_negative() || !l.rgb.is_finite())
        throw Error(a.loc, "area light radiance must be finite and non-negative");
    e.radiance = l;
    e.two_sided = a.params.get_bool("twosided", false);
    e.power = a.params.get_float("power", -1);
    return e;
}

} // namespace illum

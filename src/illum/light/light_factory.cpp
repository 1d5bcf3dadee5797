#include "illum/light/light_factory.h"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>

#include "illum/light/directional_light.h"
#include "illum/light/image_environment_light.h"
#include "illum/light/point_light.h"
#include "illum/light/spot_light.h"
#include "illum/light/uniform_environment_light.h"
#include "illum/param/spectrum_param.h"

namespace illum {

namespace {

constexpr float kDegrees = kPi / 180;

// pbrt-v4: "power" Φ multiplies the emission by Φ / k_e, k_e being the power of a unit emitter of the
// light's shape (4π for a point). pbrt-v4 normalises a light's spectrum by its illuminant only and leaves an
// RGB multiplier as it is ("we should consider the RGB separately ... but we currently don't", its
// SpectrumToPhotometric), so "rgb I" [10 10 10] with "power" [100] is 10 times brighter than [1 1 1]; scenes
// are written for that behaviour, so illum keeps it.
void normalise_to_power(const LightDesc& l, Emission& c, float power_per_unit) {
    float power = l.params.get_float("power", -1);
    if (power > 0) {
        c *= power / power_per_unit;
    }
}

// A light's emission parameter ("I", "L"), in RGB and as a spectrum. pbrt-v4 reads it as a spectrum of any
// form: "rgb", or a
// "spectrum" (named, such as "stdillum-A"; wavelength-value pairs; a file of such pairs) or "blackbody".
// A spectrum is normalised to luminance 1 ("scale /= SpectrumToPhotometric(I)"), an RGB value is not
// (pbrt-v4 normalises only its illuminant part); `scale` and `power` apply to either afterwards.
// Without the parameter: the colour space's illuminant of luminance 1, RGB (1, 1, 1).
Emission emission(const LightDesc& l, const std::string& name) {
    const Param* p = l.params.find(name);
    if (!p) return Emission(Color3(1.0f));
    if (p->type == ParamType::RGB) return Emission(*l.params.get_rgb(name));
    if (p->type != ParamType::Spectrum)
        l.params.fail(*p, fmt::format("parameter \"{}\" has type {}, expected rgb, spectrum or blackbody",
                                      name, to_string(p->type)));
    SpectrumParam s = spectrum_param(*p, SpectrumKind::Illuminant);
    return Emission(s.rgb, std::move(s.spectrum));
}

Vector3f unit_or_fail(const LightDesc& l, Vector3f v, const char* what) {
    float len = length(v);
    if (!(len > 0) || !std::isfinite(len))
        throw Error(l.loc, fmt::format("light \"{}\": {} must be a non-zero direction", l.type, what));
    return v / len;
}

} // namespace

std::unique_ptr<Light> make_light(const LightDesc& l, Diagnostics& diag) {
    float scale = l.params.get_float("scale", 1);
    if (!std::isfinite(scale) || scale < 0)
        throw Error(l.loc, fmt::format("light \"{}\": bad scale {}", l.type, scale));
    if (l.type == "point") {
        Emission i = emission(l, "I");
        Point3f from = l.params.get_point3("from").value_or(Point3f{0, 0, 0});
        Point3f p = l.world_from_light(from);
        normalise_to_power(l, i, 4 * kPi); // Φ = 4π I
        return std::make_unique<PointLight>(p, i * scale);
    }
    if (l.type == "spot") {
        Emission i = emission(l, "I");
        Point3f from = l.params.get_point3("from").value_or(Point3f{0, 0, 0});
        Point3f to = l.params.get_point3("to").value_or(Point3f{0, 0, 1});
        float cone = l.params.get_float("coneangle", 30);
        float delta = l.params.get_float("conedeltaangle", 5); // pbrt-v4's name (and RenderMan's)
        if (!(cone > 0 && cone <= 180) || !(delta >= 0))
            throw Error(l.loc,
                        fmt::format("light \"spot\": coneangle must be in (0, 180] and conedeltaangle >= 0, "
                                    "not {} and {}",
                                    cone, delta));
        Point3f p = l.world_from_light(from);
        Vector3f axis = unit_or_fail(l, l.world_from_light(to) - p, "the direction from \"from\" to \"to\"");
        float cos_end = std::cos(cone * kDegrees),
              cos_start = std::cos(std::max(0.0f, cone - delta) * kDegrees);
        normalise_to_power(l, i, 2 * kPi * ((1 - cos_start) + (cos_start - cos_end) / 2));
        return std::make_unique<SpotLight>(p, axis, i * scale, cone * kDegrees, delta * kDegrees);
    }
    if (l.type == "distant") {
        Emission e = emission(l, "L");
        Point3f from = l.params.get_point3("from").value_or(Point3f{0, 0, 0});
        Point3f to = l.params.get_point3("to").value_or(Point3f{0, 0, 1});
        // Light travels from `from` towards `to`; the light lies in direction from - to.
        Vector3f w = unit_or_fail(l, l.world_from_light(from - to), "the direction from \"to\" to \"from\"");
        float illuminance = l.params.get_float("illuminance", -1);
        if (illuminance > 0) e *= illuminance; // pbrt-v4: the RGB multiplier is kept, as for "power"
        return std::make_unique<DirectionalLight>(w, e * scale);
    }
    if (l.type == "infinite") {
        float illuminance = l.params.get_float("illuminance", -1);
        std::string sampling_name = l.params.get_string("sampling", "importance");
        EnvSampling sampling = EnvSampling::Importance;
        if (sampling_name == "uniform")
            sampling = EnvSampling::Uniform;
        else if (sampling_name == "none")
            sampling = EnvSampling::None;
        else if (sampling_name != "importance")
            throw Error(
                l.params.find("sampling")->loc,
                fmt::format("\"sampling\" must be importance, uniform or none, not \"{}\"", sampling_name));
        if (const Param* portal = l.params.find("portal")) {
            // pbrt-v4 then emits only in the directions the portal (a window quadrilateral) covers and
            // samples those better; illum keeps the whole map: the same image wherever the scene's walls
            // hide the other directions, as they do in the interiors portals are meant for.
            portal->used = true;
            diag.unsupported(portal->loc,
                             "infinite light \"portal\" is not supported: the whole environment emits and is "
                             "sampled");
        }
        std::string filename = l.params.get_string("filename", "");
        if (!filename.empty()) {
            // pbrt-v4 refuses both ("Can't specify both emission L and filename"): which one was meant
            // is not known, so neither is guessed.
            if (const Param* lp = l.params.find("L"))
                throw Error(lp->loc, "infinite light: \"L\" and \"filename\" cannot both be given");
            std::optional<EnvLayout> layout;
            std::string layout_name = l.params.get_string("layout", ""); // illum extension
            if (!layout_name.empty()) {
                layout = env_layout_from_string(layout_name);
                if (!layout)
                    throw Error(l.params.find("layout")->loc,
                                fmt::format("unknown layout \"{}\"", layout_name));
            }
            if (!std::ifstream(filename)) {
                diag.missing_file(l.params.find("filename")->loc,
                                  fmt::format("cannot read \"{}\": {}", filename, std::strerror(errno)));
                return nullptr;
            }
            EnvironmentMap map;
            try {
                map = EnvironmentMap::load(filename, layout);
            } catch (const Error& e) {
                throw Error(l.params.find("filename")->loc, e.what());
            }
            auto light =
                std::make_unique<ImageEnvironmentLight>(std::move(map), l.world_from_light, scale, sampling);
            if (illuminance > 0) {
                float e_up = light->upper_hemisphere_irradiance();
                if (e_up > 0)
                    light = std::make_unique<ImageEnvironmentLight>(light->map(), l.world_from_light,
                                                                    scale * illuminance / e_up, sampling);
            }
            if (light->map().mean_radiance().is_black())
                diag.unsupported(l.loc,
                                 fmt::format("environment map \"{}\" is black: it emits nothing", filename));
            return light;
        }
        Emission c = emission(l, "L");
        // A constant environment L gives illuminance π L on an upward surface.
        if (illuminance > 0) c *= illuminance / kPi; // pbrt-v4: the RGB multiplier is kept, as for "power"
        if (sampling != EnvSampling::Importance) {
            // Let the image light implement the sampling modes on a one-texel map.
            // (A spectral L is then rendered by its RGB, uplifted.)
            Image img(2, 1, c.rgb);
            return std::make_unique<ImageEnvironmentLight>(EnvironmentMap(std::move(img), EnvLayout::LatLong),
                                                           l.world_from_light, scale, sampling);
        }
        return std::make_unique<UniformEnvironmentLight>(c * scale);
    }
    if (l.type == "goniometric" || l.type == "projection") {
        diag.unsupported(l.loc, fmt::format("light \"{}\" is not supported yet and is skipped", l.type));
        return nullptr;
    }
    throw Error(l.loc, fmt::format("unknown light type \"{}\"", l.type));
}

} // namespace illum

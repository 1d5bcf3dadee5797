#include "illum/light/light_factory.h"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>

#include "illum/light/directional_light.h"
#include "illum/light/goniometric_light.h"
#include "illum/light/image_environment_light.h"
#include "illum/light/light_image.h"
#include "illum/light/point_light.h"
#include "illum/light/portal_environment_light.h"
#include "illum/light/projection_light.h"
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

// pbrt-v4's GoniometricLight::Create: "I" (default the illuminant), "scale", "power" (Φ = 4π I mean(Y)), and
// "filename": a square equal-area image whose Y (or R, G, B average) weighs the intensity per direction.
std::unique_ptr<Light> make_goniometric_light(const LightDesc& l, float scale, Diagnostics& diag) {
    Emission i = emission(l, "I");
    std::optional<Image> img = read_light_image(l, "goniometric light", diag);
    if (!img) return nullptr;
    if (img->width() != img->height())
        throw Error(l.params.find("filename")->loc,
                    fmt::format("goniometric light: image resolution ({}, {}) is not square: it must be an "
                                "equal-area (octahedral) map",
                                img->width(), img->height()));
    double mean_y = 0;
    for (std::size_t k = 0; k < img->pixel_count(); ++k) mean_y += img->data()[k].average();
    mean_y /= double(img->pixel_count());
    if (mean_y > 0) normalise_to_power(l, i, float(4 * kPiD * mean_y));
    return std::make_unique<GoniometricLight>(l.world_from_light, i * scale, *img);
}

// pbrt-v4's ProjectionLight::Create: "filename" (required), "fov" (90 degrees), "scale", "power" (against
// pbrt-v4's midpoint estimate of the image's luminous power). pbrt-v4 reads no "I" for it.
std::unique_ptr<Light> make_projection_light(const LightDesc& l, float scale, Diagnostics& diag) {
    float fov = l.params.get_float("fov", 90);
    if (!(fov > 0 && fov < 180))
        throw Error(l.params.find("fov")->loc,
                    fmt::format("projection light: fov must be in (0, 180), not {}", fov));
    std::optional<Image> img = read_light_image(l, "projection light", diag);
    if (!img) return nullptr;
    float power = l.params.get_float("power", -1);
    if (power > 0) {
        double k = projection_power_normalisation(*img, fov);
        if (k > 0) scale *= float(power / k);
    }
    return std::make_unique<ProjectionLight>(l.world_from_light, *img, scale, fov);
}

// pbrt-v4's "portal" of an infinite light: four points in world space (pbrt-v4 takes them from world to
// render space, not through the light's transform) forming a planar rectangle, p0 and p2 opposite.
std::optional<std::array<Point3f, 4>> read_portal(const LightDesc& l) {
    const Param* p = l.params.find("portal");
    if (!p) return std::nullopt;
    std::vector<Point3f> pts = l.params.get_point3s("portal");
    if (pts.size() != 4)
        throw Error(p->loc, fmt::format("infinite light: \"portal\" needs 4 points, not {}", pts.size()));
    std::array<Point3f, 4> portal{pts[0], pts[1], pts[2], pts[3]};
    std::string problem = portal_shape_problem(portal);
    if (!problem.empty())
        throw Error(p->loc, fmt::format("infinite light: \"portal\" is not a planar rectangle: {}", problem));
    return portal;
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
        std::optional<std::array<Point3f, 4>> portal = read_portal(l);
        if (portal && sampling != EnvSampling::Importance)
            throw Error(l.params.find("sampling")->loc,
                        "infinite light: a \"portal\" light samples through its portal; \"sampling\" cannot "
                        "be changed");
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
            if (portal)
                return std::make_unique<PortalEnvironmentLight>(light->map(), l.world_from_light,
                                                                light->scale(), *portal);
            return light;
        }
        Emission c = emission(l, "L");
        // A constant environment L gives illuminance π L on an upward surface.
        if (illuminance > 0) c *= illuminance / kPi; // pbrt-v4: the RGB multiplier is kept, as for "power"
        if (portal) {
            // pbrt-v4 makes a one-texel image of L's RGB for a portal (a spectral L is then rendered by its
            // RGB).
            Image img(8, 8, c.rgb);
            return std::make_unique<PortalEnvironmentLight>(
                EnvironmentMap(std::move(img), EnvLayout::Octahedral), l.world_from_light, scale, *portal);
        }
        if (sampling != EnvSampling::Importance) {
            // Let the image light implement the sampling modes on a one-texel map.
            // (A spectral L is then rendered by its RGB, uplifted.)
            Image img(2, 1, c.rgb);
            return std::make_unique<ImageEnvironmentLight>(EnvironmentMap(std::move(img), EnvLayout::LatLong),
                                                           l.world_from_light, scale, sampling);
        }
        return std::make_unique<UniformEnvironmentLight>(c * scale);
    }
    if (l.type == "goniometric") return make_goniometric_light(l, scale, diag);
    if (l.type == "projection") return make_projection_light(l, scale, diag);
    throw Error(l.loc, fmt::format("unknown light type \"{}\"", l.type));
}

} // namespace illum

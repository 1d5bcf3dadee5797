#include "illum/light/light_factory.h"

#include <fmt/format.h>

#include "illum/light/point_light.h"
#include "illum/light/uniform_environment_light.h"

namespace illum {

std::unique_ptr<Light> make_light(const LightDesc& l, const LightFactoryContext& ctx) {
    float scale = l.params.get_float("scale", 1);
    if (l.type == "point") {
        Color3 i(1.0f);
        if (auto rgb = l.params.get_rgb("I")) i = *rgb;
        Point3f from = l.params.get_point3("from").value_or(Point3f{0, 0, 0});
        Point3f p = l.world_from_light(from);
        float power = l.params.get_float("power", -1);
        if (power > 0) {
            // pbrt-v4: scale so the total power 4π I (in luminance) equals the given power.
            float lum = i.luminance();
            if (lum > 0) i *= power / (4 * kPi * lum);
        }
        return std::make_unique<PointLight>(p, Intensity3(i * scale));
    }
    if (l.type == "infinite") {
        if (l.params.has("filename")) {
            l.params.find("filename")->used = true;
            ctx.unsupported(l.loc, "environment map images are not supported yet; using a constant environment");
        }
        Color3 c(1.0f);
        if (auto rgb = l.params.get_rgb("L")) c = *rgb;
        return std::make_unique<UniformEnvironmentLight>(Radiance3(c * scale));
    }
    if (l.type == "distant" || l.type == "spot" || l.type == "goniometric" || l.type == "projection") {
        ctx.unsupported(l.loc, fmt::format("light \"{}\" is not supported yet and is skipped", l.type));
        return nullptr;
    }
    throw Error(l.loc, fmt::format("unknown light type \"{}\"", l.type));
}

} // namespace illum

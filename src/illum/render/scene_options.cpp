#include "illum/render/scene_options.h"

#include <cmath>
#include <fmt/format.h>

#include "illum/util/error.h"

namespace illum {

namespace {

bool bool_value(const Param& p) {
    if (p.type != ParamType::Bool || p.bools.size() != 1)
        throw Error(p.loc, fmt::format("Option \"{}\" expects true or false", p.name));
    return p.bools[0];
}

std::string string_value(const Param& p) {
    if (p.type != ParamType::String || p.strings.size() != 1)
        throw Error(p.loc, fmt::format("Option \"{}\" expects a quoted string", p.name));
    return p.strings[0];
}

double number_value(const Param& p) {
    if ((p.type != ParamType::Integer && p.type != ParamType::Float) || p.numbers.size() != 1)
        throw Error(p.loc, fmt::format("Option \"{}\" expects a number", p.name));
    return p.numbers[0];
}

} // namespace

void read_scene_options(const ParamSet& options, RenderRequest& r, Diagnostics& diag) {
    for (const Param& p : options.params()) {
        p.used = true;
        const std::string& n = p.name;
        if (n == "seed") {
            double v = number_value(p);
            if (!(v >= 0 && v <= 9007199254740992.0 && v == std::floor(v)))
                throw Error(p.loc, fmt::format("Option \"seed\" must be a non-negative integer, not {}", v));
            r.seed = std::uint64_t(v);
        } else if (n == "disablepixeljitter") {
            r.disable_pixel_jitter = bool_value(p);
        } else if (n == "disablewavelengthjitter") {
            r.disable_wavelength_jitter = bool_value(p);
        } else if (n == "forcediffuse") {
            r.force_diffuse = bool_value(p);
        } else if (n == "disabletexturefiltering") {
            r.disable_texture_filtering = bool_value(p);
        } else if (n == "rendercoordsys") {
            std::string v = string_value(p);
            if (v != "camera" && v != "cameraworld" && v != "world")
                throw Error(p.loc, fmt::format("unknown rendering coordinate system \"{}\" (use camera, "
                                               "cameraworld or world)",
                                               v));
        } else if (n == "displacementedgescale") {
            double v = number_value(p);
            if (!(v > 0) || !std::isfinite(v))
                throw Error(p.loc,
                            fmt::format("Option \"displacementedgescale\" must be positive, not {}", v));
            r.displacement_edge_scale = float(v);
        } else if (n == "msereferenceimage" || n == "msereferenceout") {
            string_value(p);
            diag.unsupported(p.loc,
                             fmt::format("Option \"{}\" is not used: compare images with `illum diff`", n));
        } else if (n == "pixelstats") {
            bool_value(p);
            diag.unsupported(p.loc,
                             "Option \"pixelstats\" is not used: illum records no per-pixel statistics "
                             "images (--stats writes the render's totals)");
        } else if (n == "wavefront") {
            bool_value(p);
            diag.unsupported(p.loc, "Option \"wavefront\" is not used: illum has one CPU renderer");
        } else {
            throw Error(p.loc, fmt::format("unknown option \"{}\"", n));
        }
    }
}

} // namespace illum

#include "illum/texture/texture_params.h"

#include <cmath>
#include <fmt/format.h>

#include "illum/param/spectrum_param.h"

namespace illum {

const ColorTexture* TextureParams::own(std::unique_ptr<ColorTexture> t) {
    color_owned_.push_back(std::move(t));
    return color_owned_.back().get();
}
const FloatTexture* TextureParams::own(std::unique_ptr<FloatTexture> t) {
    float_owned_.push_back(std::move(t));
    return float_owned_.back().get();
}
const ColorTexture* TextureParams::constant(Color3 c) {
    return own(std::make_unique<ConstantColorTexture>(c));
}
const FloatTexture* TextureParams::constant(float v) {
    return own(std::make_unique<ConstantFloatTexture>(v));
}

std::shared_ptr<const MipPyramid> TextureParams::pyramid(const std::shared_ptr<const Image>& image) {
    auto& p = pyramids_[image.get()];
    if (!p) p = std::make_shared<const MipPyramid>(image);
    return p;
}

std::optional<Color3> TextureParams::constant_color(const ParamSet& e, const std::string& name) const {
    const Param* p = e.find(name);
    if (!p) return std::nullopt;
    switch (p->type) { // ParamSet's getters refuse non-finite numbers, with the parameter's position
    case ParamType::RGB:
        return *e.get_rgb(name);
    case ParamType::Float:
        return Color3(e.get_float(name, 0));
    case ParamType::Spectrum:
        return spectrum_param_rgb(*p, SpectrumKind::Unbounded);
    default:
        e.fail(*p, fmt::format("parameter \"{}\" cannot be of type {}", name, to_string(p->type)));
    }
}

const ColorTexture* TextureParams::color(const ParamSet& e, const std::string& name,
                                         std::optional<Color3> def) {
    const Param* p = e.find(name);
    if (!p) return def ? constant(*def) : nullptr;
    if (p->type != ParamType::Texture) return constant(*constant_color(e, name));
    std::string t = e.get_texture(name);
    if (auto it = color_named_.find(t); it != color_named_.end()) {
        if (uses_footprint(it->second)) ++footprint_uses_;
        return it->second;
    }
    if (float_named_.count(t))
        throw Error(p->loc, fmt::format("texture \"{}\" is a float texture; \"{}\" needs a spectrum texture",
                                        t, name));
    throw Error(p->loc, fmt::format("undefined spectrum texture \"{}\"", t));
}

const FloatTexture* TextureParams::scalar(const ParamSet& e, const std::string& name,
                                          std::optional<float> def) {
    const Param* p = e.find(name);
    if (!p) return def ? constant(*def) : nullptr;
    if (p->type == ParamType::Texture) {
        std::string t = e.get_texture(name);
        if (auto it = float_named_.find(t); it != float_named_.end()) {
            if (uses_footprint(it->second)) ++footprint_uses_;
            return it->second;
        }
        if (color_named_.count(t))
            throw Error(
                p->loc,
                fmt::format("texture \"{}\" is a spectrum texture; \"{}\" needs a float texture", t, name));
        throw Error(p->loc, fmt::format("undefined float texture \"{}\"", t));
    }
    return constant(e.get_float(name, 0)); // finite, or ParamSet's positioned error
}

} // namespace illum

// Parameters that may be textures: a material's "reflectance" may be an "rgb", a "float", a "spectrum" or
// the name of a texture. TextureParams resolves each to a texture once, when the scene is built, so
// shading only calls evaluate(). The textures it makes (constants included) go to the storage it is
// given (the scene's); it knows the named textures defined so far (pbrt-v4: a texture may use only
// earlier ones).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "illum/image/image.h"
#include "illum/param/entity.h"
#include "illum/texture/mipmap.h"
#include "illum/texture/texture.h"
#include "illum/util/diagnostics.h"

namespace illum {

class TextureParams {
public:
    TextureParams(Diagnostics& diag, std::vector<std::unique_ptr<ColorTexture>>& color_storage,
                  std::vector<std::unique_ptr<FloatTexture>>& float_storage)
        : diag_(diag), color_owned_(color_storage), float_owned_(float_storage) {}
    TextureParams(const TextureParams&) = delete;
    TextureParams& operator=(const TextureParams&) = delete;

    Diagnostics& diagnostics() const { return diag_; }

    // A colour parameter: rgb, float (grey), spectrum or a spectrum texture's name; the constant `def` when
    // absent (nullptr when `def` is nullopt). Throws illum::Error at the parameter for a wrong type, a
    // non-finite value or an undefined texture.
    const ColorTexture* color(const ParamSet& e, const std::string& name, std::optional<Color3> def);
    // A float parameter: float or a float texture's name.
    const FloatTexture* scalar(const ParamSet& e, const std::string& name, std::optional<float> def);
    // A constant (not texturable) colour parameter: rgb, float (grey) or spectrum; nullopt when absent.
    std::optional<Color3> constant_color(const ParamSet& e, const std::string& name) const;

    const ColorTexture* own(std::unique_ptr<ColorTexture> t);
    const FloatTexture* own(std::unique_ptr<FloatTexture> t);
    const ColorTexture* constant(Color3 c);
    const FloatTexture* constant(float v);

    // Named textures, as the Texture directive defines them.
    void define(const std::string& name, const ColorTexture* t) { color_named_[name] = t; }
    void define(const std::string& name, const FloatTexture* t) { float_named_[name] = t; }

    // Images read so far, by "path|encoding", so a file used by several textures is read once.
    std::unordered_map<std::string, std::shared_ptr<const Image>>& images() { return images_; }
    // The MIP pyramid of an image, made once per image.
    std::shared_ptr<const MipPyramid> pyramid(const std::shared_ptr<const Image>& image);

    // Textures whose value depends on the footprint (filtered images, checkerboards, and textures made
    // from them). color() and scalar() count how often they hand one out, so that whoever resolves
    // parameters (a material, a texture) can tell whether it needs ray differentials: compare the count
    // before and after.
    void mark_footprint(const void* texture) { footprint_.insert(texture); }
    bool uses_footprint(const void* texture) const { return footprint_.count(texture) != 0; }
    int footprint_uses() const { return footprint_uses_; }

private:
    Diagnostics& diag_;
    std::vector<std::unique_ptr<ColorTexture>>& color_owned_;
    std::vector<std::unique_ptr<FloatTexture>>& float_owned_;
    std::unordered_map<std::string, const ColorTexture*> color_named_;
    std::unordered_map<std::string, const FloatTexture*> float_named_;
    std::unordered_map<std::string, std::shared_ptr<const Image>> images_;
    std::unordered_map<const Image*, std::shared_ptr<const MipPyramid>> pyramids_;
    std::unordered_set<const void*> footprint_;
    int footprint_uses_ = 0;
};

// An image file decoded as `encoding` says, read once per (file, encoding) into params.images(): an 8-bit
// file's sRGB values are undone and raised to `gamma` when gamma > 0 (1: "linear", the raw values v/255);
// float files are linear as they are. nullptr when the file cannot be read, which is recorded in the
// diagnostics at `loc`.
std::shared_ptr<const Image> read_encoded_image(const std::string& path, const std::string& encoding,
                                                float gamma, const SourceLocation& loc,
                                                TextureParams& params);

// The Texture directive: a float or spectrum texture of any pbrt-v4 type, defined under its name in
// `params`. Image files are read once per (file, encoding); an unreadable one is recorded in the
// diagnostics (every missing file of a scene is reported together) and replaced by a constant.
void create_texture(const TextureDesc& t, TextureParams& params);

} // namespace illum

// pbrt-v4's Texture directive: "float" or "spectrum" textures of type constant, scale, mix, directionmix,
// bilerp, checkerboard (2D and 3D), imagemap and the noise textures fbm, wrinkled, windy, marble and dots,
// over every pbrt-v4 mapping, and ptex.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>

#include "illum/image/image_io.h"
#include "illum/texture/noise_textures.h"
#include "illum/texture/pbrt_textures.h"
#include "illum/texture/ptex_texture.h"
#include "illum/texture/texture_params.h"

namespace illum {

namespace {

// pbrt-v4's TextureMapping2D::Create: "uv" (uscale, vscale, udelta, vdelta), "spherical", "cylindrical"
// and "planar" (v1, v2, udelta, vdelta), the last three in the texture's space (the inverse of the CTM at the
// Texture directive).
TextureMapping2D mapping(const TextureDesc& t) {
    std::string m = t.params.get_string("mapping", "uv");
    const Transform texture_from_world = t.world_from_texture.inverse();
    if (m == "uv")
        return TextureMapping2D::uv(t.params.get_float("uscale", 1), t.params.get_float("vscale", 1),
                                    t.params.get_float("udelta", 0), t.params.get_float("vdelta", 0));
    if (m == "spherical") return TextureMapping2D::spherical(texture_from_world);
    if (m == "cylindrical") return TextureMapping2D::cylindrical(texture_from_world);
    if (m == "planar")
        return TextureMapping2D::planar(texture_from_world,
                                        t.params.get_vector3("v1").value_or(Vector3f(1, 0, 0)),
                                        t.params.get_vector3("v2").value_or(Vector3f(0, 1, 0)),
                                        t.params.get_float("udelta", 0), t.params.get_float("vdelta", 0));
    throw Error(t.params.find("mapping")->loc,
                fmt::format("unknown texture mapping \"{}\" (use uv, spherical, "
                            "cylindrical or planar)",
                            m));
}

bool is_eight_bit(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto& ch : ext) ch = char(std::tolower(ch));
    return ext != ".exr" && ext != ".pfm" && ext != ".hdr";
}

// The exponent an 8-bit image's `encoding` asks for, checked once: 0 for "sRGB" (read_image's own
// decoding), 1 for "linear" (the raw values), g for "gamma g" (v^g).
float encoding_gamma(const TextureDesc& t, const std::string& encoding) {
    if (encoding == "sRGB") return 0;
    if (encoding == "linear") return 1;
    if (encoding.rfind("gamma ", 0) != 0)
        throw Error(t.params.find("encoding")->loc, fmt::format("unknown image encoding \"{}\"", encoding));
    char* end = nullptr;
    float gamma = std::strtof(encoding.c_str() + 6, &end);
    if (*end != '\0' || !(gamma > 0) || !std::isfinite(gamma))
        throw Error(t.params.find("encoding")->loc, fmt::format("bad image encoding \"{}\"", encoding));
    return gamma;
}

// The image of an imagemap, decoded as `encoding` says (8-bit files only; float files are linear). The
// file name was resolved against the scene's folder by the parser. nullptr (recorded in the diagnostics)
// when it cannot be read.
std::shared_ptr<const Image> load_image(const TextureDesc& t, const std::string& encoding,
                                        TextureParams& params) {
    const Param* f = t.params.find("filename");
    std::string path = t.params.get_string("filename", "");
    if (path.empty()) throw Error(t.loc, "imagemap needs \"string filename\"");
    float gamma = is_eight_bit(path) ? encoding_gamma(t, encoding) : 0;
    return read_encoded_image(path, encoding, gamma, f->loc, params);
}

// A "ptex" texture's file, read once per file; 1 or 3 channels, as pbrt-v4 accepts. nullptr (recorded in
// the diagnostics) when it cannot be read.
std::shared_ptr<const PtexFile> read_ptex(const TextureDesc& t, TextureParams& params) {
    const Param* f = t.params.find("filename");
    std::string path = t.params.get_string("filename", "");
    if (path.empty()) throw Error(t.loc, "ptex needs \"string filename\"");
    std::shared_ptr<const PtexFile> file;
    try {
        file = std::make_shared<const PtexFile>(PtexFile::read(path));
    } catch (const Error& e) {
        params.diagnostics().missing_file(f->loc, e.what());
        return nullptr;
    }
    if (file->channels != 1 && file->channels != 3)
        throw Error(f->loc, fmt::format("\"{}\": only 1- and 3-channel Ptex textures are supported (as in "
                                        "pbrt-v4); it has {}",
                                        path, file->channels));
    return file;
}

} // namespace

std::shared_ptr<const Image> read_encoded_image(const std::string& path, const std::string& encoding,
                                                float gamma, const SourceLocation& loc,
                                                TextureParams& params) {
    std::string key = path + "|" + encoding;
    if (auto it = params.images().find(key); it != params.images().end()) return it->second;
    Image img;
    try {
        img = read_image(path);
    } catch (const Error& err) {
        params.diagnostics().missing_file(loc, err.what());
        return nullptr;
    }
    if (gamma > 0 && is_eight_bit(path)) { // undo read_image's sRGB decoding, then apply the gamma asked for
        for (std::size_t i = 0; i < img.pixel_count(); ++i) {
            Color3& c = img.data()[i];
            for (int k = 0; k < 3; ++k) {
                float v = c[k];
                float enc = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
                c[k] = gamma == 1 ? enc : std::pow(enc, gamma);
            }
        }
    }
    auto ptr = std::make_shared<const Image>(std::move(img));
    params.images()[key] = ptr;
    return ptr;
}

void create_texture(const TextureDesc& t, TextureParams& params) {
    bool is_float = t.value_type == "float";
    if (!is_float && t.value_type != "spectrum")
        throw Error(t.loc,
                    fmt::format("texture type must be \"float\" or \"spectrum\", not \"{}\"", t.value_type));
    const int footprint_uses = params.footprint_uses();
    bool filters = false; // whether this texture's own value depends on the footprint
    const ColorTexture* ct = nullptr;
    const FloatTexture* ft = nullptr;
    auto f = [&](const char* n, float d) { return params.scalar(t.params, n, d); };
    auto c = [&](const char* n, Color3 d) { return params.color(t.params, n, d); };
    if (t.type == "constant") {
        if (is_float)
            ft = f("value", 1);
        else
            ct = c("value", Color3(1.0f));
    } else if (t.type == "scale") {
        const FloatTexture* s = f("scale", 1);
        if (is_float)
            ft = params.own(std::make_unique<ScaleTex<FloatTexture, float>>(f("tex", 1), s));
        else
            ct = params.own(std::make_unique<ScaleTex<ColorTexture, Color3>>(c("tex", Color3(1.0f)), s));
    } else if (t.type == "mix") {
        const FloatTexture* a = f("amount", 0.5f);
        if (is_float)
            ft = params.own(std::make_unique<MixTex<FloatTexture, float>>(f("tex1", 0), f("tex2", 1), a));
        else
            ct = params.own(std::make_unique<MixTex<ColorTexture, Color3>>(c("tex1", Color3(0.0f)),
                                                                           c("tex2", Color3(1.0f)), a));
    } else if (t.type == "checkerboard") {
        filters = true;
        int dim = t.params.get_int("dimension", 2);
        if (dim != 2 && dim != 3)
            throw Error(t.params.find("dimension")->loc,
                        fmt::format("checkerboard dimension must be 2 or 3, not {}", dim));
        if (dim == 3) {
            TextureMapping3D m(t.world_from_texture.inverse());
            if (is_float)
                ft = params.own(
                    std::make_unique<Checkerboard3D<FloatTexture, float>>(f("tex1", 1), f("tex2", 0), m));
            else
                ct = params.own(std::make_unique<Checkerboard3D<ColorTexture, Color3>>(
                    c("tex1", Color3(1.0f)), c("tex2", Color3(0.0f)), m));
        } else {
            TextureMapping2D m = mapping(t);
            if (is_float)
                ft = params.own(
                    std::make_unique<Checkerboard2D<FloatTexture, float>>(f("tex1", 1), f("tex2", 0), m));
            else
                ct = params.own(std::make_unique<Checkerboard2D<ColorTexture, Color3>>(
                    c("tex1", Color3(1.0f)), c("tex2", Color3(0.0f)), m));
        }
    } else if (t.type == "bilerp") {
        TextureMapping2D m = mapping(t);
        if (is_float)
            ft = params.own(std::make_unique<BilerpTex<FloatTexture, float>>(f("v00", 0), f("v01", 1),
                                                                             f("v10", 0), f("v11", 1), m));
        else
            ct = params.own(std::make_unique<BilerpTex<ColorTexture, Color3>>(
                c("v00", Color3(0.0f)), c("v01", Color3(1.0f)), c("v10", Color3(0.0f)),
                c("v11", Color3(1.0f)), m));
    } else if (t.type == "directionmix") {
        // pbrt-v4: dir in the texture's space, taken to render space and normalised.
        Vector3f dir =
            normalize(t.world_from_texture(t.params.get_vector3("dir").value_or(Vector3f(0, 1, 0))));
        if (is_float)
            ft = params.own(
                std::make_unique<DirectionMixTex<FloatTexture, float>>(f("tex1", 0), f("tex2", 1), dir));
        else
            ct = params.own(std::make_unique<DirectionMixTex<ColorTexture, Color3>>(
                c("tex1", Color3(0.0f)), c("tex2", Color3(1.0f)), dir));
    } else if (t.type == "imagemap") {
        std::string enc = t.params.get_string(
            "encoding", is_eight_bit(t.params.get_string("filename", "")) ? "sRGB" : "linear");
        std::string wrap = t.params.get_string("wrap", "repeat");
        WrapMode w = WrapMode::Repeat;
        if (wrap == "clamp")
            w = WrapMode::Clamp;
        else if (wrap == "black")
            w = WrapMode::Black;
        else if (wrap == "octahedralsphere")
            w = WrapMode::OctahedralSphere;
        else if (wrap != "repeat")
            throw Error(t.params.find("wrap")->loc, fmt::format("unknown wrap mode \"{}\"", wrap));
        // pbrt-v4's MIPMapFilterOptions: "filter" (default bilinear) and "maxanisotropy" (8, EWA only).
        std::string filter = t.params.get_string("filter", "bilinear");
        MipFilter mf = MipFilter::Bilinear;
        if (filter == "point")
            mf = MipFilter::Point;
        else if (filter == "trilinear")
            mf = MipFilter::Trilinear;
        else if (filter == "ewa" || filter == "EWA")
            mf = MipFilter::EWA;
        else if (filter != "bilinear")
            throw Error(t.params.find("filter")->loc, fmt::format("unknown texture filter \"{}\"", filter));
        float max_anisotropy = t.params.get_float("maxanisotropy", 8);
        if (!(max_anisotropy >= 1))
            throw Error(t.params.find("maxanisotropy")->loc,
                        fmt::format("maxanisotropy must be at least 1, not {}", max_anisotropy));
        float scale = t.params.get_float("scale", 1);
        bool invert = t.params.get_bool("invert", false);
        TextureMapping2D m = mapping(t);
        if (auto image = load_image(t, enc, params); image && !image->empty()) {
            filters = true;
            FilteredImage data(MipMap(params.pyramid(image), mf, w, max_anisotropy), scale, invert);
            if (is_float)
                ft = params.own(std::make_unique<ImageFloatTexture>(data, m));
            else
                ct = params.own(std::make_unique<ImageColorTexture>(data, m));
        } else if (is_float) { // the build fails with every missing file listed; go on to find the others
            ft = params.constant(0.0f);
        } else {
            ct = params.constant(Color3(0.0f));
        }
    } else if (t.type == "fbm" || t.type == "wrinkled" || t.type == "windy" || t.type == "marble") {
        // pbrt-v4 has fbm, wrinkled and windy as float textures only, marble as a spectrum texture only.
        if (is_float == (t.type == "marble"))
            throw Error(t.loc, fmt::format("\"{}\" is a {} texture in pbrt-v4", t.type,
                                           t.type == "marble" ? "spectrum" : "float"));
        filters = true; // the octaves finer than the footprint are left out
        TextureMapping3D m(t.world_from_texture.inverse());
        int octaves = t.params.get_int("octaves", 8);
        float omega = t.params.get_float("roughness", 0.5f);
        if (octaves < 0 || octaves > 64)
            throw Error(t.params.find("octaves")->loc,
                        fmt::format("octaves must be in [0, 64], not {}", octaves));
        if (t.type == "fbm")
            ft = params.own(std::make_unique<FbmTexture>(m, octaves, omega));
        else if (t.type == "wrinkled")
            ft = params.own(std::make_unique<WrinkledTexture>(m, octaves, omega));
        else if (t.type == "windy")
            ft = params.own(std::make_unique<WindyTexture>(m));
        else
            ct = params.own(std::make_unique<MarbleTexture>(m, octaves, omega, t.params.get_float("scale", 1),
                                                            t.params.get_float("variation", 0.2f)));
    } else if (t.type == "dots") {
        // As pbrt-v4 (5f7a606) renders it: its Create passes the "inside" parameter where the constructor
        // takes the texture outside the dots (and "outside" for inside), so a scene's "inside" fills the
        // space between the dots. Kept, so that scenes render as in pbrt-v4.
        TextureMapping2D m = mapping(t);
        if (is_float)
            ft = params.own(
                std::make_unique<DotsTex<FloatTexture, float>>(f("outside", 0), f("inside", 1), m));
        else
            ct = params.own(std::make_unique<DotsTex<ColorTexture, Color3>>(c("outside", Color3(0.0f)),
                                                                            c("inside", Color3(1.0f)), m));
    } else if (t.type == "ptex") {
        float gamma = encoding_gamma(t, t.params.get_string("encoding", "gamma 2.2"));
        float scale = t.params.get_float("scale", 1);
        if (std::shared_ptr<const PtexFile> file = read_ptex(t, params)) {
            filters = true;
            PtexLookup l(std::move(file), gamma, scale);
            if (is_float)
                ft = params.own(std::make_unique<PtexFloatTexture>(std::move(l)));
            else
                ct = params.own(std::make_unique<PtexColorTexture>(std::move(l)));
        } else if (is_float) { // the build fails with every missing file listed; go on to find the others
            ft = params.constant(0.0f);
        } else {
            ct = params.constant(Color3(0.0f));
        }
    } else {
        throw Error(t.loc, fmt::format("unknown texture type \"{}\"", t.type));
    }
    if (filters || params.footprint_uses() > footprint_uses)
        params.mark_footprint(is_float ? (const void*)ft : ct);
    if (is_float)
        params.define(t.name, ft);
    else
        params.define(t.name, ct);
}

} // namespace illum

#include "illum/scene/build.h"

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/registry.h"
#include "illum/bsdf/shared_bxdf_material.h"
#include "illum/bsdf/textured_model_material.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "illum/bsdf/pbrt_materials.h"
#include "illum/geometry/cylinder.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/sphere.h"
#include "illum/image/image_io.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/light_factory.h"
#include "illum/radiometry/spectra.h"
#include "illum/scene/pbrt/ply.h"
#include "illum/texture/pbrt_textures.h"

namespace illum {

namespace {

class Builder {
public:
    Builder(const SceneDesc& desc, const BuildOptions& options)
        : desc_(desc), options_(options), scene_(std::make_unique<Scene>()) {}

    std::unique_ptr<Scene> build() {
        build_film_and_camera();
        build_render_request();
        build_materials();
        for (const ShapeDesc& s : desc_.shapes) build_shape(s);
        for (const LightDesc& l : desc_.lights) build_light(l);
        build_instances();
        report_unused_parameters();
        scene_->warnings.insert(scene_->warnings.begin(), desc_.warnings.begin(), desc_.warnings.end());
        scene_->finalize();
        return std::move(scene_);
    }

private:
    // A recognised feature that illum does not support: one warning, or an error under --strict.
    void unsupported(const SourceLocation& loc, const std::string& what) {
        if (options_.strict) throw Error(loc, what + " (unsupported; --strict)");
        std::string w = loc.file.empty() ? what : loc.to_string() + ": " + what;
        for (auto& existing : scene_->warnings)
            if (existing == w) return;
        scene_->warnings.push_back(w);
    }

    // pbrt-v4 rejects parameters that nothing reads; illum warns (an error under --strict), naming each one,
    // so a misspelt or unsupported parameter never changes the image silently.
    void report_unused_parameters() {
        auto check = [&](const EntityDesc& e, const char* what) {
            for (const Param* p : e.params.unused())
                unsupported(p->loc, fmt::format("{} \"{}\": parameter \"{} {}\" is not used", what, e.type,
                                                to_string(p->type), p->name));
        };
        check(desc_.camera, "camera");
        check(desc_.film, "film");
        check(desc_.sampler, "sampler");
        check(desc_.filter, "pixel filter");
        check(desc_.integrator, "integrator");
        for (const auto& m : desc_.materials) check(m, "material");
        for (const auto& t : desc_.textures) check(t, "texture");
        for (const auto& sh : desc_.shapes) check(sh, "shape");
        for (const auto& a : desc_.area_lights) check(a, "area light");
        for (const auto& l : desc_.lights) check(l, "light");
    }

    void build_film_and_camera() {
        const EntityDesc& film = desc_.film;
        if (film.type != "rgb" && film.type != "gbuffer" && film.type != "spectral")
            throw Error(film.loc, fmt::format("unknown film type \"{}\"", film.type));
        if (film.type != "rgb")
            unsupported(film.loc, fmt::format("film \"{}\" is rendered as \"rgb\"", film.type));
        int w = film.params.get_int("xresolution", 1280), h = film.params.get_int("yresolution", 720);
        if (w <= 0 || h <= 0 || w > 65536 || h > 65536)
            throw Error(film.loc, fmt::format("film resolution {}x{} is out of range", w, h));
        scene_->width = w;
        scene_->height = h;
        scene_->request.output = film.params.get_string("filename", "");

        const EntityDesc& f = desc_.filter;
        Vector2f radius{f.params.get_float("xradius", -1), f.params.get_float("yradius", -1)};
        if (f.type == "box" || f.type == "triangle" || f.type == "gaussian") {
            scene_->filter = make_filter(f.type, radius, f.params.get_float("sigma", 0.5f));
        } else if (f.type == "mitchell" || f.type == "sinc") {
            unsupported(f.loc, fmt::format("pixel filter \"{}\" is approximated by a gaussian", f.type));
            scene_->filter = make_filter("gaussian", {1.5f, 1.5f});
        } else {
            throw Error(f.loc, fmt::format("unknown pixel filter \"{}\"", f.type));
        }

        const CameraDesc& c = desc_.camera;
        Transform world_from_camera = c.camera_from_world.inverse();
        float lens_radius = c.params.get_float("lensradius", 0);
        float focal_distance = c.params.get_float("focaldistance", 1e6f);
        if (lens_radius < 0) throw Error(c.loc, "camera lensradius must be non-negative");
        if (!(focal_distance > 0)) throw Error(c.loc, "camera focaldistance must be positive");
        Screen screen = PerspectiveCamera::default_screen(w, h);
        float frame = c.params.get_float("frameaspectratio", 0);
        if (frame > 0)
            screen = frame > 1 ? Screen{-frame, frame, -1, 1} : Screen{-1, 1, -1 / frame, 1 / frame};
        auto sw = c.params.get_floats("screenwindow");
        if (!sw.empty()) {
            if (sw.size() != 4)
                throw Error(c.params.find("screenwindow")->loc, "screenwindow needs 4 values");
            screen = {sw[0], sw[1], sw[2], sw[3]};
        }
        if (c.type == "perspective" || c.type.empty()) {
            float fov = c.params.get_float("fov", 90);
            if (!(fov > 0 && fov < 180))
                throw Error(c.loc, fmt::format("camera fov {} is out of (0, 180)", fov));
            scene_->camera = std::make_unique<PerspectiveCamera>(world_from_camera, w, h, fov, lens_radius,
                                                                 focal_distance, &screen);
        } else if (c.type == "orthographic") {
            scene_->camera = std::make_unique<OrthographicCamera>(world_from_camera, w, h, lens_radius,
                                                                  focal_distance, &screen);
        } else if (c.type == "realistic" || c.type == "spherical") {
            unsupported(c.loc, fmt::format("camera \"{}\" is approximated by a perspective camera", c.type));
            scene_->camera = std::make_unique<PerspectiveCamera>(world_from_camera, w, h, 90.0f);
        } else {
            throw Error(c.loc, fmt::format("unknown camera type \"{}\"", c.type));
        }
    }

    void build_render_request() {
        RenderRequest& r = scene_->request;
        const EntityDesc& in = desc_.integrator;
        r.max_depth = in.params.get_int("maxdepth", 5);
        if (r.max_depth < -1) throw Error(in.loc, "maxdepth must be -1 (unbounded) or non-negative");
        if (in.type == "path" || in.type == "simplepath") {
            r.integrator = "path";
        } else if (in.type == "direct" || in.type == "directlighting") {
            r.integrator = "direct"; // illum's own, and pbrt-v3's name for it
        } else if (in.type == "volpath") {
            r.integrator = "path"; // surfaces only; media are reported where they are declared
        } else if (in.type == "bdpt" || in.type == "mlt" || in.type == "sppm" || in.type == "lightpath" ||
                   in.type == "randomwalk" || in.type == "simplevolpath") {
            unsupported(in.loc, fmt::format("integrator \"{}\" is rendered with \"path\"", in.type));
            r.integrator = "path";
        } else if (in.type == "ambientocclusion" || in.type == "aov") {
            unsupported(in.loc, fmt::format("integrator \"{}\" is rendered with \"path\"", in.type));
            r.integrator = "path";
        } else {
            throw Error(in.loc, fmt::format("unknown integrator \"{}\"", in.type));
        }
        const EntityDesc& s = desc_.sampler;
        r.spp = s.params.get_int("pixelsamples", 16);
        if (r.spp <= 0) throw Error(s.loc, "pixelsamples must be positive");
        if (s.type == "independent")
            r.sampler = "independent";
        else if (s.type == "sobol" || s.type == "zsobol" || s.type == "paddedsobol")
            r.sampler = "sobol";
        else if (s.type == "halton" || s.type == "pmj02bn" || s.type == "stratified") {
            unsupported(s.loc, fmt::format("sampler \"{}\" is replaced by \"sobol\"", s.type));
            r.sampler = "sobol";
        } else {
            throw Error(s.loc, fmt::format("unknown sampler \"{}\"", s.type));
        }
    }

    // ---- spectra, textures and materials ----------------------------------------------------------

    // A spectrum parameter as RGB: named (pbrt-v4's metal, glass and illuminant names), blackbody,
    // sampled (λ value pairs) or a file of such pairs. Illuminants are normalised to luminance 1.
    Color3 spectrum_rgb(const Param& p, bool illuminant) {
        p.used = true;
        if (p.strings.size() == 1 && p.strings[0] == "blackbody") {
            if (p.numbers.empty() || !(p.numbers[0] > 0))
                throw Error(p.loc, "blackbody needs a positive temperature");
            return blackbody_rgb(p.numbers[0]);
        }
        SampledSpectrum s;
        if (p.strings.size() == 1 && p.numbers.empty()) {
            if (auto c = named_spectrum_rgb(p.strings[0])) return *c;
            std::string file = p.strings[0];
            if (!file.empty() && file[0] != '/' && !desc_.base_dir.empty())
                file = desc_.base_dir + "/" + file;
            std::ifstream in(file);
            if (!in)
                throw Error(p.loc,
                            fmt::format("unknown named spectrum or unreadable file \"{}\"", p.strings[0]));
            std::string line;
            std::vector<double> v;
            while (std::getline(in, line)) {
                auto hash = line.find('#');
                if (hash != std::string::npos) line.resize(hash);
                std::istringstream ls(line);
                double x;
                while (ls >> x) v.push_back(x);
            }
            if (v.size() < 2 || v.size() % 2)
                throw Error(
                    p.loc, fmt::format("spectrum file \"{}\" needs (wavelength, value) pairs", p.strings[0]));
            for (std::size_t i = 0; i < v.size(); i += 2) {
                s.lambda.push_back(v[i]);
                s.value.push_back(v[i + 1]);
            }
        } else {
            if (p.numbers.size() < 2 || p.numbers.size() % 2)
                throw Error(p.loc, "a sampled spectrum needs (wavelength, value) pairs");
            for (std::size_t i = 0; i < p.numbers.size(); i += 2) {
                s.lambda.push_back(p.numbers[i]);
                s.value.push_back(p.numbers[i + 1]);
            }
        }
        for (std::size_t i = 1; i < s.lambda.size(); ++i)
            if (!(s.lambda[i] > s.lambda[i - 1])) throw Error(p.loc, "spectrum wavelengths must increase");
        return illuminant ? illuminant_spectrum_to_rgb(s) : unbounded_spectrum_to_rgb(s);
    }

    const ColorTexture* constant_color(Color3 c) {
        scene_->color_textures.push_back(std::make_unique<ConstantColorTexture>(c));
        return scene_->color_textures.back().get();
    }
    const FloatTexture* constant_float(float v) {
        scene_->float_textures.push_back(std::make_unique<ConstantFloatTexture>(v));
        return scene_->float_textures.back().get();
    }
    template <class T, class... A>
    const ColorTexture* own_color(A&&... a) {
        scene_->color_textures.push_back(std::make_unique<T>(std::forward<A>(a)...));
        return scene_->color_textures.back().get();
    }
    template <class T, class... A>
    const FloatTexture* own_float(A&&... a) {
        scene_->float_textures.push_back(std::make_unique<T>(std::forward<A>(a)...));
        return scene_->float_textures.back().get();
    }

    // A colour parameter: rgb, float (grey), spectrum or a named texture. nullptr when absent and def is
    // nullopt.
    const ColorTexture* color_param(const EntityDesc& e, const std::string& name, std::optional<Color3> def) {
        const Param* p = e.params.find(name);
        if (!p) return def ? constant_color(*def) : nullptr;
        switch (p->type) {
        case ParamType::RGB: {
            Color3 c = *e.params.get_rgb(name);
            if (!c.is_finite()) throw Error(p->loc, fmt::format("\"{}\" is not finite", name));
            return constant_color(c);
        }
        case ParamType::Float:
            return constant_color(Color3(e.params.get_float(name, 0)));
        case ParamType::Spectrum:
            return constant_color(spectrum_rgb(*p, false));
        case ParamType::Texture: {
            std::string t = e.params.get_texture(name);
            if (auto it = color_textures_.find(t); it != color_textures_.end()) return it->second;
            if (float_textures_.count(t))
                throw Error(p->loc,
                            fmt::format("texture \"{}\" is a float texture; \"{}\" needs a spectrum texture",
                                        t, name));
            throw Error(p->loc, fmt::format("undefined spectrum texture \"{}\"", t));
        }
        default:
            e.params.fail(*p, fmt::format("parameter \"{}\" cannot be of type {}", name, to_string(p->type)));
        }
    }

    const FloatTexture* float_param(const EntityDesc& e, const std::string& name, std::optional<float> def) {
        const Param* p = e.params.find(name);
        if (!p) return def ? constant_float(*def) : nullptr;
        if (p->type == ParamType::Texture) {
            std::string t = e.params.get_texture(name);
            if (auto it = float_textures_.find(t); it != float_textures_.end()) return it->second;
            if (color_textures_.count(t))
                throw Error(p->loc,
                            fmt::format("texture \"{}\" is a spectrum texture; \"{}\" needs a float texture",
                                        t, name));
            throw Error(p->loc, fmt::format("undefined float texture \"{}\"", t));
        }
        float v = e.params.get_float(name, 0);
        if (!std::isfinite(v)) throw Error(p->loc, fmt::format("\"{}\" is not finite", name));
        return constant_float(v);
    }

    // A scalar index of refraction: float, or a spectrum reduced to its value at 550 nm (named glasses)
    // or the mean of its RGB.
    float eta_param(const EntityDesc& e, const std::string& name, float def) {
        const Param* p = e.params.find(name);
        if (!p) return def;
        float eta = def;
        if (p->type == ParamType::Spectrum) {
            Color3 c = spectrum_rgb(*p, false);
            eta = c.average();
            if (!(p->strings.size() == 1 && p->strings[0].rfind("glass-", 0) == 0))
                unsupported(p->loc, fmt::format("spectrally varying \"{}\" is rendered with its mean {:.4g}",
                                                name, eta));
        } else if (p->type == ParamType::Texture) {
            p->used = true;
            unsupported(p->loc, fmt::format("a textured \"{}\" is rendered with {}", name, def));
        } else {
            eta = e.params.get_float(name, def);
        }
        if (!(eta > 0 && eta <= 100))
            throw Error(p->loc, fmt::format("\"{}\" must be in (0, 100], got {}", name, eta));
        return eta;
    }

    RoughnessParams roughness(const EntityDesc& e, const std::string& prefix = "") {
        RoughnessParams r;
        const FloatTexture* both = float_param(e, prefix + "roughness", 0.0f);
        r.u = e.params.has(prefix + "uroughness") ? float_param(e, prefix + "uroughness", 0.0f) : both;
        r.v = e.params.has(prefix + "vroughness") ? float_param(e, prefix + "vroughness", 0.0f) : both;
        r.remap = e.params.get_bool("remaproughness", true);
        return r;
    }

    UVMapping mapping(const TextureDesc& t) {
        std::string m = t.params.get_string("mapping", "uv");
        if (m != "uv") unsupported(t.loc, fmt::format("texture mapping \"{}\" is replaced by \"uv\"", m));
        return {t.params.get_float("uscale", 1), t.params.get_float("vscale", 1),
                t.params.get_float("udelta", 0), t.params.get_float("vdelta", 0)};
    }

    std::shared_ptr<const Image> load_texture_image(const TextureDesc& t, const std::string& encoding) {
        std::string file = t.params.get_string("filename", "");
        if (file.empty()) throw Error(t.loc, "imagemap needs \"string filename\"");
        std::string path = file;
        if (path[0] != '/' && !desc_.base_dir.empty()) path = desc_.base_dir + "/" + path;
        std::string key = path + "|" + encoding;
        if (auto it = images_.find(key); it != images_.end()) return it->second;
        Image img;
        try {
            img = read_image(path);
        } catch (const Error& err) {
            throw Error(t.params.find("filename")->loc, err.what());
        }
        std::string ext = std::filesystem::path(path).extension().string();
        for (auto& ch : ext) ch = char(std::tolower(ch));
        bool eight_bit = ext != ".exr" && ext != ".pfm" && ext != ".hdr";
        // read_image decodes 8-bit images as sRGB; "linear" asks for the raw values, "gamma g" for v^g.
        if (eight_bit && encoding != "sRGB") {
            float gamma = 1;
            if (encoding.rfind("gamma ", 0) == 0)
                gamma = std::stof(encoding.substr(6));
            else if (encoding != "linear")
                throw Error(t.loc, fmt::format("unknown image encoding \"{}\"", encoding));
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
        images_[key] = ptr;
        return ptr;
    }

    void build_texture(const TextureDesc& t) {
        bool is_float = t.value_type == "float";
        if (!is_float && t.value_type != "spectrum")
            throw Error(t.loc, fmt::format("texture type must be \"float\" or \"spectrum\", not \"{}\"",
                                           t.value_type));
        const ColorTexture* ct = nullptr;
        const FloatTexture* ft = nullptr;
        auto tex_param_f = [&](const char* n, float d) { return float_param(t, n, d); };
        auto tex_param_c = [&](const char* n, Color3 d) { return color_param(t, n, d); };
        if (t.type == "constant") {
            if (is_float)
                ft = tex_param_f("value", 1);
            else
                ct = tex_param_c("value", Color3(1.0f));
        } else if (t.type == "scale") {
            const FloatTexture* s = tex_param_f("scale", 1);
            if (is_float)
                ft = own_float<ScaleTex<FloatTexture, float>>(tex_param_f("tex", 1), s);
            else
                ct = own_color<ScaleTex<ColorTexture, Color3>>(tex_param_c("tex", Color3(1.0f)), s);
        } else if (t.type == "mix") {
            const FloatTexture* a = tex_param_f("amount", 0.5f);
            if (is_float)
                ft =
                    own_float<MixTex<FloatTexture, float>>(tex_param_f("tex1", 0), tex_param_f("tex2", 1), a);
            else
                ct = own_color<MixTex<ColorTexture, Color3>>(tex_param_c("tex1", Color3(0.0f)),
                                                             tex_param_c("tex2", Color3(1.0f)), a);
        } else if (t.type == "checkerboard") {
            int dim = t.params.get_int("dimension", 2);
            if (dim != 2) unsupported(t.loc, "a 3D checkerboard is rendered as a 2D one");
            UVMapping m = mapping(t);
            if (is_float)
                ft = own_float<Checkerboard2D<FloatTexture, float>>(tex_param_f("tex1", 1),
                                                                    tex_param_f("tex2", 0), m);
            else
                ct = own_color<Checkerboard2D<ColorTexture, Color3>>(tex_param_c("tex1", Color3(1.0f)),
                                                                     tex_param_c("tex2", Color3(0.0f)), m);
        } else if (t.type == "imagemap") {
            std::string file = t.params.get_string("filename", "");
            std::string ext = std::filesystem::path(file).extension().string();
            for (auto& ch : ext) ch = char(std::tolower(ch));
            bool eight_bit = ext != ".exr" && ext != ".pfm" && ext != ".hdr";
            std::string enc = t.params.get_string("encoding", eight_bit ? "sRGB" : "linear");
            std::string wrap = t.params.get_string("wrap", "repeat");
            WrapMode w = WrapMode::Repeat;
            if (wrap == "clamp")
                w = WrapMode::Clamp;
            else if (wrap == "black")
                w = WrapMode::Black;
            else if (wrap == "octahedralsphere")
                unsupported(t.loc, "wrap \"octahedralsphere\" is replaced by \"repeat\"");
            else if (wrap != "repeat")
                throw Error(t.params.find("wrap")->loc, fmt::format("unknown wrap mode \"{}\"", wrap));
            std::string filter = t.params.get_string("filter", "bilinear");
            if (filter != "bilinear" && filter != "point" && filter != "trilinear" && filter != "ewa")
                throw Error(t.params.find("filter")->loc,
                            fmt::format("unknown texture filter \"{}\"", filter));
            t.params.get_float("maxanisotropy", 8);
            ImageTextureData data(load_texture_image(t, enc), w, t.params.get_float("scale", 1),
                                  t.params.get_bool("invert", false));
            UVMapping m = mapping(t);
            if (is_float)
                ft = own_float<ImageFloatTexture>(data, m);
            else
                ct = own_color<ImageColorTexture>(data, m);
        } else if (t.type == "bilerp" || t.type == "directionmix" || t.type == "dots" || t.type == "fbm" ||
                   t.type == "marble" || t.type == "ptex" || t.type == "windy" || t.type == "wrinkled") {
            unsupported(t.loc, fmt::format("texture \"{}\" is approximated by a constant 0.5", t.type));
            if (is_float)
                ft = constant_float(0.5f);
            else
                ct = constant_color(Color3(0.5f));
        } else {
            throw Error(t.loc, fmt::format("unknown texture type \"{}\"", t.type));
        }
        if (is_float)
            float_textures_[t.name] = ft;
        else
            color_textures_[t.name] = ct;
    }

    const Material* own(std::unique_ptr<Material> m) {
        scene_->materials.push_back(std::move(m));
        return scene_->materials.back().get();
    }

    int int_param(const EntityDesc& m, const char* name, int def, int lo, int hi) {
        int v = m.params.get_int(name, def);
        if (v < lo || v > hi)
            throw Error(m.params.find(name)->loc, fmt::format("\"{}\" must be in [{}, {}]", name, lo, hi));
        return v;
    }

    const ConductorMaterial* conductor(const EntityDesc& m, const std::string& prefix) {
        const ColorTexture* refl = color_param(m, "reflectance", std::nullopt);
        const ColorTexture* eta = color_param(m, prefix + "eta", std::nullopt);
        const ColorTexture* k = color_param(m, prefix + "k", std::nullopt);
        if (refl && (eta || k))
            unsupported(m.loc, "conductor with both \"reflectance\" and eta/k uses \"reflectance\"");
        if (!eta) eta = constant_color(*named_spectrum_rgb("metal-Cu-eta"));
        if (!k) k = constant_color(*named_spectrum_rgb("metal-Cu-k"));
        auto c = std::make_unique<ConductorMaterial>(eta, k, refl, roughness(m, prefix));
        const ConductorMaterial* ptr = c.get();
        own(std::move(c));
        return ptr;
    }

    // The layer of a coated material: pbrt-v4's "thickness" (0.01), "albedo" (0), "g" (0), "maxdepth" (10)
    // and "nsamples" (1).
    LayerParams layer_params(const EntityDesc& m) {
        LayerParams l;
        if (const Param* t = m.params.find("thickness");
            t && t->type == ParamType::Float && !(m.params.get_float("thickness", 0.01f) >= 0))
            throw Error(t->loc, "\"thickness\" must be non-negative");
        l.thickness = float_param(m, "thickness", 0.01f);
        l.albedo = color_param(m, "albedo", Color3(0.0f));
        l.g = float_param(m, "g", 0.0f);
        l.max_depth = int_param(m, "maxdepth", 10, 1, 1000);
        l.samples = int_param(m, "nsamples", 1, 1, 1000);
        return l;
    }

    // illum's own reflection models (`illum brdf list`) by name, with constant parameters, e.g.
    //   Material "ward" "rgb rd" [0.2 0.1 0.05] "rgb rs" [0.04 0.04 0.04] "float alpha_x" [0.1]
    // (pbrt-v4's names come first: "conductor" and "dielectric" take pbrt-v4's parameters). The model is
    // built once and shared by every hit.
    const Material* model_material(const EntityDesc& m, const ModelSpec& spec) {
        std::map<std::string, std::string> values;
        std::map<std::string, const Param*> textured;
        for (const Param& p : m.params.params()) {
            if (p.name == "type") continue; // MakeNamedMaterial's own
            p.used = true;
            auto number = [](double v) { return fmt::format("{}", v); };
            switch (p.type) {
            case ParamType::Float:
            case ParamType::Integer:
                if (p.numbers.size() == 1) values[p.name] = number(p.numbers[0]);
                break;
            case ParamType::RGB:
                if (p.numbers.size() == 3)
                    values[p.name] =
                        number(p.numbers[0]) + "," + number(p.numbers[1]) + "," + number(p.numbers[2]);
                break;
            case ParamType::String:
                if (p.strings.size() == 1) values[p.name] = p.strings[0];
                break;
            case ParamType::Bool:
                if (p.bools.size() == 1) values[p.name] = p.bools[0] ? "true" : "false";
                break;
            case ParamType::Texture:
                textured[p.name] = &p;
                continue;
            default:
                m.params.fail(p, fmt::format("material \"{}\": parameter \"{}\" cannot be of type {}",
                                             spec.name, p.name, to_string(p.type)));
            }
            if (!values.count(p.name))
                m.params.fail(
                    p, fmt::format("parameter \"{}\" of material \"{}\" needs one value", p.name, spec.name));
        }
        ParamValues resolved;
        std::unique_ptr<BxDF> bxdf;
        try {
            resolved = resolve_params(spec, values);
            bxdf = spec.make(resolved); // with the textured parameters at their defaults
        } catch (const Error& e) {
            throw Error(m.loc, e.what());
        }
        // The albedo pass shows the directional albedo at normal incidence.
        AlbedoEstimate a = directional_albedo(*bxdf, {0, 0, 1}, spec.delta, 16, 4096, 1);
        Color3 albedo(float(a.mc[0]), float(a.mc[1]), float(a.mc[2]));
        if (textured.empty()) return own(std::make_unique<SharedBxDFMaterial>(std::move(bxdf), albedo));

        // illum's own models (`illum brdf list`) with textured parameters: placed per hit.
        if (!spec.factory.place)
            throw Error(m.loc, fmt::format("material \"{}\" cannot have textured parameters", spec.name));
        std::vector<ShadingArgs::Value> args;
        for (const ParamSpec& ps : spec.params) {
            ShadingArgs::Value v{ps.name,       ps.kind,       {}, {}, nullptr, nullptr,
                                 float(ps.min), float(ps.max), -1};
            for (std::size_t g = 0; g < spec.unit_sums.size(); ++g)
                for (const std::string& name : spec.unit_sums[g])
                    if (name == ps.name) v.unit_sum_group = int(g);
            if (auto t = textured.find(ps.name); t != textured.end()) {
                if (ps.kind == ParamKind::Rgb)
                    v.color = color_param(m, ps.name, std::nullopt);
                else if (ps.kind == ParamKind::Scalar)
                    v.scalar = float_param(m, ps.name, std::nullopt);
                else
                    m.params.fail(*t->second, fmt::format("parameter \"{}\" of \"{}\" cannot be a texture",
                                                          ps.name, spec.name));
                textured.erase(t);
            } else if (!resolved.has(ps.name)) {
                continue; // an optional parameter not given
            } else if (ps.kind == ParamKind::Rgb) {
                v.constant = resolved.rgb(ps.name);
            } else if (ps.kind == ParamKind::Scalar || ps.kind == ParamKind::Integer) {
                v.constant = Color3(resolved.scalar(ps.name));
            } else {
                v.text = resolved.str(ps.name);
            }
            args.push_back(std::move(v));
        }
        if (!textured.empty())
            m.params.fail(*textured.begin()->second, fmt::format("material \"{}\" has no parameter \"{}\"",
                                                                 spec.name, textured.begin()->first));
        return own(std::make_unique<TexturedModelMaterial>(spec, std::move(args), albedo));
    }

    const Material* make_material(const EntityDesc& m, const std::string& type) {
        if (type == "diffuse")
            return own(std::make_unique<DiffuseMaterial>(color_param(m, "reflectance", Color3(0.5f))));
        if (type == "conductor") return conductor(m, "");
        if (type == "dielectric")
            return own(std::make_unique<DielectricMaterial>(eta_param(m, "eta", 1.5f), roughness(m)));
        if (type == "thindielectric")
            return own(std::make_unique<ThinDielectricMaterial>(eta_param(m, "eta", 1.5f)));
        if (type == "coateddiffuse")
            return own(std::make_unique<CoatedDiffuseMaterial>(color_param(m, "reflectance", Color3(0.5f)),
                                                               eta_param(m, "eta", 1.5f), roughness(m),
                                                               layer_params(m)));
        if (type == "coatedconductor") {
            float ieta = eta_param(m, "interface.eta", 1.5f);
            RoughnessParams coat = roughness(m, "interface.");
            const ConductorMaterial* c = conductor(m, "conductor.");
            return own(std::make_unique<CoatedConductorMaterial>(ieta, coat, c, roughness(m, "conductor."),
                                                                 layer_params(m)));
        }
        if (type == "diffusetransmission")
            return own(std::make_unique<DiffuseTransmissionMaterial>(
                color_param(m, "reflectance", Color3(0.25f)), color_param(m, "transmittance", Color3(0.25f)),
                m.params.get_float("scale", 1)));
        if (type == "interface") return own(std::make_unique<InterfaceMaterial>());
        if (type == "mix") {
            auto names = m.params.get_strings("materials");
            if (names.size() != 2)
                throw Error(m.params.has("materials") ? m.params.find("materials")->loc : m.loc,
                            "mix needs \"string materials\" with two named materials");
            const Material* ab[2];
            for (int i = 0; i < 2; ++i) {
                auto it = built_named_.find(names[i]);
                if (it == built_named_.end())
                    throw Error(m.params.find("materials")->loc,
                                fmt::format("undefined named material \"{}\"", names[i]));
                ab[i] = it->second;
            }
            return own(std::make_unique<MixMaterial>(ab[0], ab[1], float_param(m, "amount", 0.5f)));
        }
        if (type == "measured" || type == "subsurface" || type == "hair") {
            unsupported(m.loc, fmt::format("material \"{}\" is approximated by a grey diffuse one", type));
            for (const Param& p : m.params.params()) p.used = true;
            return own(std::make_unique<DiffuseMaterial>(constant_color(Color3(0.5f))));
        }
        for (const ModelSpec& spec : bxdf_models())
            if (spec.name == type) return model_material(m, spec);
        throw Error(m.loc, fmt::format("unknown material type \"{}\"", type));
    }

    void build_materials() {
        // Textures and materials may refer to earlier ones only, as in pbrt-v4; textures come first.
        for (const TextureDesc& t : desc_.textures) build_texture(t);
        for (const MaterialDesc& m : desc_.materials) {
            std::string type = m.name.empty() ? m.type : m.params.get_string("type", m.type);
            if (type.empty())
                throw Error(m.loc, fmt::format("named material \"{}\" has no \"string type\"", m.name));
            materials_.push_back(make_material(m, type));
            if (!m.name.empty()) built_named_[m.name] = materials_.back();
        }
        default_material_ = make_material(EntityDesc{"diffuse", {}, {}}, "diffuse");
    }

    const Material* resolve(const MaterialRef& ref, const SourceLocation& loc) {
        if (ref.index >= 0 && ref.index < int(materials_.size())) return materials_[ref.index];
        if (!ref.name.empty()) {
            auto it = desc_.named_materials.find(ref.name);
            if (it == desc_.named_materials.end())
                throw Error(loc, fmt::format("undefined named material \"{}\"", ref.name));
            return materials_.at(it->second);
        }
        return default_material_;
    }

    // pbrt-v4's DiffuseAreaLight: L (default: the colour space's illuminant, luminance 1) times `scale`;
    // a spectrum L is normalised to luminance 1 first ("scale /= SpectrumToPhotometric(L)"), an RGB L is
    // not (pbrt-v4 normalises only its illuminant part, D65 of luminance 1). With `power` P > 0 the
    // radiance is further multiplied by P / (π · (twosided ? 2 : 1) · area), where area is that of one
    // primitive (pbrt-v4 makes one light per triangle, so each triangle of a mesh emits P).
    struct Emission {
        Color3 radiance;
        bool two_sided = false;
        float power = -1;
        Radiance3 for_area(float area) const {
            Color3 l = radiance;
            if (power > 0 && area > 0) l *= power / (kPi * (two_sided ? 2.0f : 1.0f) * area);
            return Radiance3(l);
        }
    };

    std::optional<Emission> area_light_of(const ShapeDesc& s) {
        if (s.area_light < 0) return std::nullopt;
        const EntityDesc& a = desc_.area_lights.at(s.area_light);
        if (a.type != "diffuse") throw Error(a.loc, fmt::format("unknown area light type \"{}\"", a.type));
        Color3 l(1.0f);
        if (const Param* p = a.params.find("L")) {
            if (p->type == ParamType::RGB)
                l = *a.params.get_rgb("L");
            else if (p->type == ParamType::Spectrum)
                l = spectrum_rgb(*p, true);
            else if (p->type == ParamType::Float)
                l = Color3(a.params.get_float("L", 1));
            else
                a.params.fail(*p, fmt::format("parameter \"L\" cannot be of type {}", to_string(p->type)));
        }
        if (a.params.has("filename")) {
            a.params.find("filename")->used = true;
            unsupported(a.params.find("filename")->loc,
                        "an image-textured area light is rendered with its L");
        }
        l *= a.params.get_float("scale", 1);
        if (l.has_negative() || !l.is_finite())
            throw Error(a.loc, "area light radiance must be finite and non-negative");
        Emission e{l, a.params.get_bool("twosided", false), a.params.get_float("power", -1)};
        return e;
    }

    void add_mesh(const ShapeDesc& s, std::unique_ptr<TriangleMesh> mesh) {
        mesh->flip_normal = s.reverse_orientation != s.world_from_object.swaps_handedness();
        mesh->transform(s.world_from_object);
        mesh->finalize();
        std::vector<const Light*> tri_lights;
        if (auto e = area_light_of(s)) {
            for (std::uint32_t t = 0; t < mesh->triangle_count(); ++t) {
                scene_->light_shapes.push_back(std::make_unique<TriangleShape>(mesh.get(), t));
                auto light = std::make_unique<DiffuseAreaLight>(
                    scene_->light_shapes.back().get(), e->for_area(mesh->triangle_area(t)), e->two_sided);
                light->set_alpha(alpha_of(s));
                scene_->lights.push_back(std::move(light));
                tri_lights.push_back(scene_->lights.back().get());
            }
        }
        scene_->accelerator.add_mesh(std::move(mesh), resolve(s.material, s.loc), std::move(tri_lights),
                                     alpha_of(s));
    }

    // pbrt-v4's "alpha" of a shape, a float or a float texture; nullptr when the shape is opaque.
    const FloatTexture* alpha_of(const ShapeDesc& s) {
        const Param* a = s.params.find("alpha");
        if (!a) return nullptr;
        if (a->type == ParamType::Float && s.params.get_float("alpha", 1) >= 1) return nullptr;
        return float_param(s, "alpha", 1.0f);
    }

    // Where a shape's parameter was written (the shape's own position when it was not).
    static SourceLocation param_loc(const ShapeDesc& s, const char* name) {
        const Param* p = s.params.find(name);
        return p ? p->loc : s.loc;
    }

    // pbrt-v4's "phimax" in degrees, (0, 360], as radians.
    static float phimax_of(const ShapeDesc& s) {
        float phimax = s.params.get_float("phimax", 360);
        if (!(phimax > 0 && phimax <= 360))
            throw Error(param_loc(s, "phimax"),
                        fmt::format("{} phimax must be in (0, 360], not {}", s.type, phimax));
        return phimax * (kPi / 180);
    }

    // Outward normals flip under ReverseOrientation and under a transform that swaps handedness (pbrt-v4).
    static bool flip_of(const ShapeDesc& s) {
        return s.reverse_orientation != s.world_from_object.swaps_handedness();
    }

    // A sphere, disk or cylinder with its cut-out and its area light (one light for the whole shape,
    // `power` normalised by its exact area).
    void add_analytic_shape(const ShapeDesc& s, std::unique_ptr<AnalyticShape> shape) {
        shape->set_alpha(alpha_of(s));
        const Light* light = nullptr;
        if (auto e = area_light_of(s)) {
            auto l =
                std::make_unique<DiffuseAreaLight>(shape.get(), e->for_area(shape->area()), e->two_sided);
            l->set_alpha(shape->alpha());
            light = l.get();
            scene_->lights.push_back(std::move(l));
        }
        scene_->accelerator.add_shape(std::move(shape), resolve(s.material, s.loc), light);
    }

    void build_shape(const ShapeDesc& s) {
        if (!s.world_from_object.matrix().is_finite()) throw Error(s.loc, "shape transform is not finite");
        // A constant alpha of 0 removes the shape (pbrt-v4 does the same); any other alpha below 1 is a
        // cut-out (alpha_of).
        if (const Param* a = s.params.find("alpha"))
            if (a->type == ParamType::Float && s.params.get_float("alpha", 1) <= 0) return;
        if (s.type == "trianglemesh") {
            auto mesh = std::make_unique<TriangleMesh>();
            mesh->p = s.params.get_point3s("P");
            auto idx = s.params.get_ints("indices");
            if (mesh->p.empty()) throw Error(s.loc, "trianglemesh needs \"point3 P\"");
            if (idx.empty()) {
                if (mesh->p.size() != 3)
                    throw Error(s.loc, "trianglemesh without \"indices\" must have 3 vertices");
                idx = {0, 1, 2};
            }
            if (idx.size() % 3 != 0)
                throw Error(s.params.find("indices")->loc,
                            fmt::format("trianglemesh has {} indices, not a multiple of 3", idx.size()));
            for (int i : idx)
                if (i < 0 || std::size_t(i) >= mesh->p.size())
                    throw Error(
                        s.params.find("indices")->loc,
                        fmt::format("trianglemesh index {} is out of range (the mesh has {} vertices)", i,
                                    mesh->p.size()));
            mesh->indices.assign(idx.begin(), idx.end());
            mesh->n = s.params.get_normals("N");
            if (!mesh->n.empty() && mesh->n.size() != mesh->p.size())
                throw Error(s.params.find("N")->loc, "trianglemesh has a different number of N and P");
            mesh->uv = s.params.get_point2s("uv");
            if (mesh->uv.empty()) mesh->uv = s.params.get_point2s("st");
            if (!mesh->uv.empty() && mesh->uv.size() != mesh->p.size())
                throw Error(s.loc, "trianglemesh has a different number of uv and P");
            add_mesh(s, std::move(mesh));
        } else if (s.type == "sphere") {
            float r = s.params.get_float("radius", 1);
            if (!(r > 0)) throw Error(param_loc(s, "radius"), "sphere radius must be positive");
            float zmin = s.params.get_float("zmin", -r), zmax = s.params.get_float("zmax", r);
            // pbrt-v4 orders zmin, zmax and clamps them to [-r, r]; an empty range is an error here.
            float z0 = std::clamp(std::min(zmin, zmax), -r, r), z1 = std::clamp(std::max(zmin, zmax), -r, r);
            if (!(z0 < z1))
                throw Error(
                    param_loc(s, s.params.has("zmin") ? "zmin" : "zmax"),
                    fmt::format("sphere zmin ({}) and zmax ({}) leave nothing of the sphere of radius {}",
                                zmin, zmax, r));
            add_analytic_shape(s, std::make_unique<SphereShape>(s.world_from_object, r, zmin, zmax,
                                                                phimax_of(s), flip_of(s)));
        } else if (s.type == "disk") {
            float r = s.params.get_float("radius", 1), ri = s.params.get_float("innerradius", 0);
            float h = s.params.get_float("height", 0);
            if (!(r > 0) || !(ri >= 0) || !(ri < r) || !std::isfinite(h))
                throw Error(s.loc, "disk needs 0 <= innerradius < radius and a finite height");
            add_analytic_shape(
                s, std::make_unique<DiskShape>(s.world_from_object, h, r, ri, flip_of(s), phimax_of(s)));
        } else if (s.type == "plymesh") {
            std::string file = s.params.get_string("filename", "");
            if (file.empty()) throw Error(s.loc, "plymesh needs \"string filename\"");
            TriangleMeshData data;
            try {
                data = read_ply(file);
            } catch (const Error& e) {
                throw Error(s.params.find("filename")->loc, e.what());
            }
            if (data.indices.empty()) {
                unsupported(s.loc, fmt::format("plymesh \"{}\" has no triangles and is skipped", file));
                return;
            }
            if (s.params.has("displacement")) unsupported(s.loc, "plymesh displacement is ignored");
            auto mesh = std::make_unique<TriangleMesh>();
            mesh->p = std::move(data.positions);
            mesh->n = std::move(data.normals);
            mesh->uv = std::move(data.uvs);
            mesh->indices.assign(data.indices.begin(), data.indices.end());
            add_mesh(s, std::move(mesh));
        } else if (s.type == "bilinearmesh") {
            // Each bilinear patch (p00, p10, p01, p11) becomes the two triangles (p00, p10, p11) and
            // (p00, p11, p01), whose normals agree with the patch's dp/du x dp/dv: exact for planar
            // patches, a two-triangle approximation of curved ones.
            auto mesh = std::make_unique<TriangleMesh>();
            mesh->p = s.params.get_point3s("P");
            auto idx = s.params.get_ints("indices");
            if (mesh->p.empty()) throw Error(s.loc, "bilinearmesh needs \"point3 P\"");
            if (idx.empty()) {
                if (mesh->p.size() != 4)
                    throw Error(s.loc, "bilinearmesh without \"indices\" must have 4 vertices");
                idx = {0, 1, 2, 3};
            }
            if (idx.size() % 4 != 0)
                throw Error(s.params.find("indices")->loc,
                            fmt::format("bilinearmesh has {} indices, not a multiple of 4", idx.size()));
            for (int i : idx)
                if (i < 0 || std::size_t(i) >= mesh->p.size())
                    throw Error(
                        s.params.find("indices")->loc,
                        fmt::format("bilinearmesh index {} is out of range (the mesh has {} vertices)", i,
                                    mesh->p.size()));
            for (std::size_t q = 0; q < idx.size(); q += 4) {
                std::uint32_t a = idx[q], b = idx[q + 1], c = idx[q + 2], d = idx[q + 3];
                mesh->indices.insert(mesh->indices.end(), {a, b, d, a, d, c});
            }
            mesh->n = s.params.get_normals("N");
            if (!mesh->n.empty() && mesh->n.size() != mesh->p.size())
                throw Error(s.params.find("N")->loc, "bilinearmesh has a different number of N and P");
            mesh->uv = s.params.get_point2s("uv");
            if (!mesh->uv.empty() && mesh->uv.size() != mesh->p.size())
                throw Error(s.loc, "bilinearmesh has a different number of uv and P");
            if (mesh->uv.empty() && idx.size() == 4 && mesh->p.size() == 4)
                mesh->uv = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
            add_mesh(s, std::move(mesh));
        } else if (s.type == "cylinder") {
            float r = s.params.get_float("radius", 1), z0 = s.params.get_float("zmin", -1),
                  z1 = s.params.get_float("zmax", 1);
            if (!(r > 0)) throw Error(param_loc(s, "radius"), "cylinder radius must be positive");
            if (!(z0 != z1) || !std::isfinite(z0) || !std::isfinite(z1))
                throw Error(param_loc(s, s.params.has("zmin") ? "zmin" : "zmax"),
                            "cylinder needs finite zmin != zmax");
            add_analytic_shape(
                s, std::make_unique<CylinderShape>(s.world_from_object, r, z0, z1, phimax_of(s), flip_of(s)));
        } else if (s.type == "loopsubdiv" || s.type == "curve" || s.type == "cone" ||
                   s.type == "paraboloid" || s.type == "hyperboloid") {
            unsupported(s.loc, fmt::format("shape \"{}\" is not supported yet and is skipped", s.type));
        } else {
            throw Error(s.loc, fmt::format("unknown shape type \"{}\"", s.type));
        }
    }

    // ObjectInstance: flattened, each use copies the definition's shapes under world_from_instance (no
    // Embree instancing yet: memory grows with the number of uses). Area lights in instances are
    // ignored, as pbrt-v4 does.
    // pbrt's ObjectBegin/ObjectInstance: each definition is built once, in its own space, as an Embree
    // prototype; each use is an Embree instance of it (memory does not grow with the number of uses).
    void build_instances() {
        std::map<std::string, std::uint32_t> prototypes;
        for (const InstanceUse& use : desc_.instance_uses) {
            auto it = desc_.instances.find(use.name);
            if (it == desc_.instances.end())
                throw Error(use.loc, fmt::format("undefined object \"{}\" in ObjectInstance", use.name));
            if (!use.world_from_instance.matrix().is_finite())
                throw Error(use.loc, "instance transform is not finite");
            auto p = prototypes.find(use.name);
            if (p == prototypes.end()) {
                std::uint32_t id = scene_->accelerator.begin_prototype();
                for (const ShapeDesc& shape : it->second.shapes) {
                    ShapeDesc copy = shape;
                    if (copy.area_light >= 0) {
                        unsupported(shape.loc, "area lights in object instances are ignored (as in pbrt-v4)");
                        copy.area_light = -1;
                    }
                    build_shape(copy);
                }
                scene_->accelerator.end_prototype();
                p = prototypes.emplace(use.name, id).first;
            }
            scene_->accelerator.add_instance(p->second, use.world_from_instance);
        }
    }

    void build_light(const LightDesc& l) {
        LightFactoryContext ctx{
            [this](const SourceLocation& loc, const std::string& what) { unsupported(loc, what); }};
        if (auto light = make_light(l, ctx)) scene_->lights.push_back(std::move(light));
    }

    const SceneDesc& desc_;
    BuildOptions options_;
    std::unique_ptr<Scene> scene_;
    std::vector<const Material*> materials_;
    std::unordered_map<std::string, const Material*> built_named_;
    std::unordered_map<std::string, const ColorTexture*> color_textures_;
    std::unordered_map<std::string, const FloatTexture*> float_textures_;
    std::unordered_map<std::string, std::shared_ptr<const Image>> images_;
    const Material* default_material_ = nullptr;
};

} // namespace

std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const BuildOptions& options) {
    return Builder(desc, options).build();
}

} // namespace illum

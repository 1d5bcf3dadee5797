#include "illum/scene/build.h"

#include <cmath>
#include <fmt/format.h>

#include "illum/light/diffuse_area_light.h"
#include "illum/light/light_factory.h"
#include "illum/scene/pbrt/ply.h"

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
        if (!desc_.instance_uses.empty())
            unsupported(desc_.instance_uses.front().loc, "object instancing (ObjectInstance) is ignored");
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

    void build_film_and_camera() {
        const EntityDesc& film = desc_.film;
        if (film.type != "rgb" && film.type != "gbuffer" && film.type != "spectral")
            throw Error(film.loc, fmt::format("unknown film type \"{}\"", film.type));
        if (film.type != "rgb") unsupported(film.loc, fmt::format("film \"{}\" is rendered as \"rgb\"", film.type));
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
        if (frame > 0) screen = frame > 1 ? Screen{-frame, frame, -1, 1} : Screen{-1, 1, -1 / frame, 1 / frame};
        auto sw = c.params.get_floats("screenwindow");
        if (!sw.empty()) {
            if (sw.size() != 4) throw Error(c.params.find("screenwindow")->loc, "screenwindow needs 4 values");
            screen = {sw[0], sw[1], sw[2], sw[3]};
        }
        if (c.type == "perspective" || c.type.empty()) {
            float fov = c.params.get_float("fov", 90);
            if (!(fov > 0 && fov < 180)) throw Error(c.loc, fmt::format("camera fov {} is out of (0, 180)", fov));
            scene_->camera =
                std::make_unique<PerspectiveCamera>(world_from_camera, w, h, fov, lens_radius, focal_distance, &screen);
        } else if (c.type == "orthographic") {
            scene_->camera =
                std::make_unique<OrthographicCamera>(world_from_camera, w, h, lens_radius, focal_distance, &screen);
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
        if (s.type == "independent") r.sampler = "independent";
        else if (s.type == "sobol" || s.type == "zsobol" || s.type == "paddedsobol") r.sampler = "sobol";
        else if (s.type == "halton" || s.type == "pmj02bn" || s.type == "stratified") {
            unsupported(s.loc, fmt::format("sampler \"{}\" is replaced by \"sobol\"", s.type));
            r.sampler = "sobol";
        } else {
            throw Error(s.loc, fmt::format("unknown sampler \"{}\"", s.type));
        }
    }

    const ColorTexture* color_param(const EntityDesc& e, const std::string& name, Color3 def) {
        Color3 c = def;
        if (const Param* p = e.params.find(name)) {
            switch (p->type) {
            case ParamType::RGB: c = *e.params.get_rgb(name); break;
            case ParamType::Float: c = Color3(e.params.get_float(name, 0)); break;
            case ParamType::Texture:
                unsupported(p->loc, fmt::format("texture \"{}\" for \"{}\" is not supported yet; using its default",
                                                e.params.get_texture(name), name));
                break;
            case ParamType::Spectrum:
                p->used = true;
                unsupported(p->loc, fmt::format("spectrum \"{}\" is approximated by its default", name));
                break;
            default: e.params.fail(*p, fmt::format("parameter \"{}\" cannot be of type {}", name, to_string(p->type)));
            }
        }
        scene_->color_textures.push_back(std::make_unique<ConstantColorTexture>(c));
        return scene_->color_textures.back().get();
    }

    const Material* make_material(const EntityDesc& m, const std::string& type) {
        if (type == "diffuse") {
            auto mat = std::make_unique<DiffuseMaterial>(color_param(m, "reflectance", Color3(0.5f)));
            scene_->materials.push_back(std::move(mat));
            return scene_->materials.back().get();
        }
        static const char* known[] = {"coateddiffuse", "coatedconductor", "conductor", "dielectric",
                                      "thindielectric", "diffusetransmission", "hair", "measured",
                                      "mix", "subsurface", "interface"};
        for (const char* k : known)
            if (type == k) {
                unsupported(m.loc, fmt::format("material \"{}\" is approximated by a grey diffuse one", type));
                scene_->materials.push_back(std::make_unique<DiffuseMaterial>(grey()));
                return scene_->materials.back().get();
            }
        throw Error(m.loc, fmt::format("unknown material type \"{}\"", type));
    }

    const ColorTexture* grey() {
        scene_->color_textures.push_back(std::make_unique<ConstantColorTexture>(Color3(0.5f)));
        return scene_->color_textures.back().get();
    }

    void build_materials() {
        for (const MaterialDesc& m : desc_.materials) {
            std::string type = m.name.empty() ? m.type : m.params.get_string("type", m.type);
            if (type.empty()) throw Error(m.loc, fmt::format("named material \"{}\" has no \"string type\"", m.name));
            materials_.push_back(make_material(m, type));
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

    struct Emission {
        Radiance3 radiance;
        bool two_sided = false;
    };

    std::optional<Emission> area_light_of(const ShapeDesc& s) {
        if (s.area_light < 0) return std::nullopt;
        const EntityDesc& a = desc_.area_lights.at(s.area_light);
        if (a.type != "diffuse") throw Error(a.loc, fmt::format("unknown area light type \"{}\"", a.type));
        Color3 l(1.0f);
        if (auto rgb = a.params.get_rgb("L")) l = *rgb;
        else if (a.params.has("L")) {
            a.params.find("L")->used = true;
            unsupported(a.params.find("L")->loc, "spectral L is approximated by white");
        }
        l *= a.params.get_float("scale", 1);
        if (a.params.has("power")) {
            a.params.find("power")->used = true;
            unsupported(a.params.find("power")->loc, "area light \"power\" is ignored");
        }
        if (l.has_negative()) throw Error(a.loc, "area light radiance must be non-negative");
        return Emission{Radiance3(l), a.params.get_bool("twosided", false)};
    }

    void add_mesh(const ShapeDesc& s, std::unique_ptr<TriangleMesh> mesh) {
        mesh->flip_normal = s.reverse_orientation != s.world_from_object.swaps_handedness();
        mesh->transform(s.world_from_object);
        mesh->finalize();
        std::vector<const Light*> tri_lights;
        if (auto e = area_light_of(s)) {
            for (std::uint32_t t = 0; t < mesh->triangle_count(); ++t) {
                scene_->light_shapes.push_back(std::make_unique<TriangleShape>(mesh.get(), t));
                scene_->lights.push_back(std::make_unique<DiffuseAreaLight>(scene_->light_shapes.back().get(),
                                                                           e->radiance, e->two_sided));
                tri_lights.push_back(scene_->lights.back().get());
            }
        }
        scene_->accelerator.add_mesh(std::move(mesh), resolve(s.material, s.loc), std::move(tri_lights));
    }

    void build_shape(const ShapeDesc& s) {
        if (!s.world_from_object.matrix().is_finite()) throw Error(s.loc, "shape transform is not finite");
        if (s.type == "trianglemesh") {
            auto mesh = std::make_unique<TriangleMesh>();
            mesh->p = s.params.get_point3s("P");
            auto idx = s.params.get_ints("indices");
            if (mesh->p.empty()) throw Error(s.loc, "trianglemesh needs \"point3 P\"");
            if (idx.empty()) {
                if (mesh->p.size() != 3) throw Error(s.loc, "trianglemesh without \"indices\" must have 3 vertices");
                idx = {0, 1, 2};
            }
            if (idx.size() % 3 != 0)
                throw Error(s.params.find("indices")->loc, fmt::format("trianglemesh has {} indices, not a multiple of 3", idx.size()));
            for (int i : idx)
                if (i < 0 || std::size_t(i) >= mesh->p.size())
                    throw Error(s.params.find("indices")->loc,
                                fmt::format("trianglemesh index {} is out of range (the mesh has {} vertices)", i, mesh->p.size()));
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
            if (!(r > 0)) throw Error(s.loc, "sphere radius must be positive");
            for (const char* p : {"zmin", "zmax", "phimax"})
                if (s.params.has(p)) {
                    s.params.find(p)->used = true;
                    unsupported(s.params.find(p)->loc, fmt::format("partial spheres (\"{}\") are rendered whole", p));
                }
            Point3f c = s.world_from_object(Point3f{0, 0, 0});
            Vector3f ax = s.world_from_object(Vector3f{1, 0, 0}), ay = s.world_from_object(Vector3f{0, 1, 0}),
                     az = s.world_from_object(Vector3f{0, 0, 1});
            float sx = length(ax), sy = length(ay), sz = length(az);
            if (std::abs(sx - sy) > 1e-4f * sx || std::abs(sx - sz) > 1e-4f * sx)
                unsupported(s.loc, "a non-uniformly scaled sphere is rendered with its mean scale");
            float radius = r * (sx + sy + sz) / 3;
            bool flip = s.reverse_orientation != s.world_from_object.swaps_handedness();
            auto sphere = std::make_unique<SphereShape>(c, radius, flip);
            const Light* light = nullptr;
            if (auto e = area_light_of(s)) {
                scene_->lights.push_back(std::make_unique<DiffuseAreaLight>(sphere.get(), e->radiance, e->two_sided));
                light = scene_->lights.back().get();
            }
            scene_->accelerator.add_sphere(std::move(sphere), resolve(s.material, s.loc), light);
        } else if (s.type == "disk") {
            float r = s.params.get_float("radius", 1), ri = s.params.get_float("innerradius", 0);
            float h = s.params.get_float("height", 0);
            if (!(r > 0) || ri < 0 || ri >= r) throw Error(s.loc, "disk needs 0 <= innerradius < radius");
            bool flip = s.reverse_orientation != s.world_from_object.swaps_handedness();
            auto disk = std::make_unique<DiskShape>(s.world_from_object, h, r, ri, flip);
            const Light* light = nullptr;
            if (auto e = area_light_of(s)) {
                scene_->lights.push_back(std::make_unique<DiffuseAreaLight>(disk.get(), e->radiance, e->two_sided));
                light = scene_->lights.back().get();
            }
            scene_->accelerator.add_disk(std::move(disk), resolve(s.material, s.loc), light);
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
        } else if (s.type == "bilinearmesh" || s.type == "cylinder" || s.type == "loopsubdiv" ||
                   s.type == "curve" || s.type == "cone" || s.type == "paraboloid" || s.type == "hyperboloid") {
            unsupported(s.loc, fmt::format("shape \"{}\" is not supported yet and is skipped", s.type));
        } else {
            throw Error(s.loc, fmt::format("unknown shape type \"{}\"", s.type));
        }
    }

    void build_light(const LightDesc& l) {
        LightFactoryContext ctx{[this](const SourceLocation& loc, const std::string& what) { unsupported(loc, what); }};
        if (auto light = make_light(l, ctx)) scene_->lights.push_back(std::move(light));
    }

    const SceneDesc& desc_;
    BuildOptions options_;
    std::unique_ptr<Scene> scene_;
    std::vector<const Material*> materials_;
    const Material* default_material_ = nullptr;
};

} // namespace

std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const BuildOptions& options) {
    return Builder(desc, options).build();
}

} // namespace illum

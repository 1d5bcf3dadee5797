// The scene builder only orchestrates (DESIGN.md §1, §6): each entity kind is created from its own
// parameters beside the code that defines it (camera/create_camera, render/create_render_request,
// texture/create_texture, bsdf/create_material, geometry/create_shape, light/area_emission and
// light/light_factory); here they are called in pbrt-v4's order and their results wired together.
#include "illum/scene/build.h"

#include <fmt/format.h>
#include <map>
#include <unordered_map>

#include "illum/bsdf/create_material.h"
#include "illum/bsdf/force_diffuse_material.h"
#include "illum/camera/create_camera.h"
#include "illum/camera/create_sensor.h"
#include "illum/geometry/create_shape.h"
#include "illum/light/area_emission.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/light_factory.h"
#include "illum/light/moving_area_light.h"
#include "illum/medium/create_medium.h"
#include "illum/medium/homogeneous_medium.h"
#include "illum/render/create_render_request.h"
#include "illum/render/scene_options.h"
#include "illum/texture/texture_params.h"

namespace illum {

namespace {

class Builder {
public:
    Builder(const SceneDesc& desc, const BuildOptions& options)
        : desc_(desc), diag_(options.strict), scene_(std::make_unique<Scene>()),
          textures_(diag_, scene_->color_textures, scene_->float_textures) {}

    std::unique_ptr<Scene> build() {
        FilmSettings film = create_film(desc_.film, diag_);
        scene_->width = film.width;
        scene_->height = film.height;
        scene_->pixel_bounds = film.pixel_bounds;
        scene_->camera_loc = desc_.camera.loc;
        scene_->camera_type = desc_.camera.type.empty() ? "perspective" : desc_.camera.type;
        scene_->filter = create_filter(desc_.filter, diag_);
        scene_->camera = create_camera(desc_.camera, film, diag_);
        scene_->color_space = color_space();
        scene_->sensor = create_sensor(desc_.film, desc_.camera, *scene_->color_space, diag_);
        scene_->request = create_render_request(desc_.integrator, desc_.sampler, diag_);
        scene_->request.output = film.filename;
        scene_->request.save_fp16 = film.save_fp16;
        read_scene_options(desc_.options, scene_->request, diag_);
        set_shutter();
        build_media();
        scene_->camera_medium = medium_named(desc_.camera.medium, desc_.camera.medium_loc);
        build_materials();
        // Camera rays carry differentials only when some material filters its textures over them.
        for (const auto& m : scene_->materials) {
            if (scene_->request.disable_texture_filtering) m->needs_texture_differentials = false;
            scene_->texture_filtering |= m->needs_texture_differentials;
        }
        for (const ShapeDesc& s : desc_.shapes) add_shape(s);
        for (const LightDesc& l : desc_.lights) add_light(l);
        add_instances();
        diag_.throw_if_files_missing();
        report_unused_parameters();
        diag_.add_warnings(desc_.warnings, desc_.unsupported);
        scene_->warnings = diag_.warnings();
        scene_->unsupported = diag_.unsupported_uses();
        scene_->finalize();
        return std::move(scene_);
    }

private:
    const RGBColorSpace* color_space() {
        const RGBColorSpace* cs = RGBColorSpace::named(desc_.color_space);
        if (!cs)
            throw Error(fmt::format("unknown ColorSpace \"{}\" (use srgb, rec2020, aces2065-1 or dci-p3)",
                                    desc_.color_space));
        return cs;
    }

    // pbrt-v4 rejects parameters that nothing reads; illum warns (an error under --strict), naming each one,
    // so a misspelt or unsupported parameter never changes the image silently.
    void report_unused_parameters() {
        auto check = [&](const EntityDesc& e, const char* what) {
            for (const Param* p : e.params.unused())
                diag_.unsupported(p->loc, fmt::format("{} \"{}\": parameter \"{} {}\" is not used", what,
                                                      e.type, to_string(p->type), p->name));
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
        for (const auto& [name, m] : desc_.media) check(m, "medium");
    }

    // MakeNamedMedium: every medium, created once; shapes, the camera and lights refer to them by name.
    void build_media() {
        for (const auto& [name, m] : desc_.media) {
            CreatedMedium c = create_medium(m, diag_);
            media_[name] = {c.medium.get(), scene_->medium_reports.size()};
            scene_->medium_reports.push_back({name, c.info.type, c.info.bytes, {}});
            scene_->media.push_back(std::move(c.medium));
        }
        if (!desc_.media.empty() && scene_->request.integrator != "volpath" &&
            scene_->request.integrator != "bdpt")
            diag_.unsupported(desc_.integrator.loc,
                              fmt::format("integrator \"{}\" renders surfaces only: the scene's media are "
                                          "ignored (use volpath)",
                                          scene_->request.integrator));
    }

    // The medium of a MediumInterface name ("" is vacuum); an undefined name is an error at the directive.
    const Medium* medium_named(const std::string& name, const SourceLocation& loc) {
        if (name.empty()) return nullptr;
        auto it = media_.find(name);
        if (it == media_.end())
            throw Error(loc,
                        fmt::format("medium \"{}\" was never made (no MakeNamedMedium before this)", name));
        return it->second.medium;
    }

    // A shape's MediumInterface when it separates two media (else none: the ray's medium carries on). A
    // material that encloses a medium (subsurface) makes that the inside.
    const MediumInterface* medium_interface_of(const ShapeDesc& s, const Material* material) {
        const Medium* inside = medium_named(s.inside_medium, s.medium_loc);
        const Medium* outside = medium_named(s.outside_medium, s.medium_loc);
        if (material && material->interior()) {
            if (inside != outside)
                diag_.unsupported(s.medium_loc, "a subsurface material's own medium replaces the shape's "
                                                "inside medium");
            auto [it, fresh] = interior_reports_.try_emplace(material, scene_->medium_reports.size());
            if (fresh)
                scene_->medium_reports.push_back(
                    {fmt::format("(subsurface material of the shape at {})", s.loc.to_string()),
                     material->interior()->evaluated_at_entry() ? "homogeneous, textured (at each entry)"
                                                                : "homogeneous",
                     sizeof(HomogeneousMedium),
                     {}});
            scene_->medium_reports[it->second].bounded_by.push_back(
                fmt::format("inside \"{}\" at {}", s.type, s.loc.to_string()));
            scene_->medium_interfaces.push_back({material->interior(), outside});
            return &scene_->medium_interfaces.back();
        }
        if (inside == outside) return nullptr;
        for (const std::string* n : {&s.inside_medium, &s.outside_medium})
            if (!n->empty())
                scene_->medium_reports[media_.at(*n).report].bounded_by.push_back(
                    fmt::format("{} \"{}\" at {}", n == &s.inside_medium ? "inside" : "outside", s.type,
                                s.loc.to_string()));
        scene_->medium_interfaces.push_back({inside, outside});
        return &scene_->medium_interfaces.back();
    }

    void build_materials() {
        // Textures and materials may refer to earlier ones only, as in pbrt-v4; textures come first.
        for (const TextureDesc& t : desc_.textures) create_texture(t, textures_);
        MaterialContext ctx{textures_, scene_->materials, named_};
        for (const MaterialDesc& m : desc_.materials) {
            std::string type = m.name.empty() ? m.type : m.params.get_string("type", m.type);
            if (type.empty())
                throw Error(m.loc, fmt::format("named material \"{}\" has no \"string type\"", m.name));
            materials_.push_back(create_material(m, type, ctx));
            if (!m.name.empty()) named_[m.name] = materials_.back();
        }
        default_material_ = create_material(EntityDesc{"diffuse", {}, {}}, "diffuse", ctx);
        if (scene_->request.force_diffuse) force_diffuse();
    }

    // Option "forcediffuse": every material (a mix's parts included, through the mix) is replaced by its
    // diffuse stand-in.
    void force_diffuse() {
        std::unordered_map<const Material*, const Material*> forced;
        auto wrap = [&](const Material*& m) {
            auto [it, fresh] = forced.try_emplace(m, nullptr);
            if (fresh) {
                scene_->materials.push_back(std::make_unique<ForceDiffuseMaterial>(m));
                scene_->materials.back()->needs_texture_differentials = m && m->needs_texture_differentials;
                it->second = scene_->materials.back().get();
            }
            m = it->second;
        };
        for (const Material*& m : materials_) wrap(m);
        for (auto& [name, m] : named_) wrap(m);
        wrap(default_material_);
        // No surface scatters by a delta lobe now, so volpath traces no caustics from the lights.
        for (auto& m : scene_->materials) m->may_be_specular = false;
    }

    const Material* material_of(const MaterialRef& ref, const SourceLocation& loc) {
        if (ref.index >= 0 && ref.index < int(materials_.size())) return materials_[ref.index];
        if (!ref.name.empty()) {
            auto it = desc_.named_materials.find(ref.name);
            if (it == desc_.named_materials.end())
                throw Error(loc, fmt::format("undefined named material \"{}\"", ref.name));
            return materials_.at(it->second);
        }
        return default_material_;
    }

    // Motion blur: the camera's shutter interval, in which each camera sample draws its time, and the
    // camera's own motion (pbrt-v4 animates world_from_camera, the inverse of the CTM at Camera).
    void set_shutter() {
        const CameraDesc& c = desc_.camera;
        scene_->shutter_open = c.params.get_float("shutteropen", 0);
        scene_->shutter_close = c.params.get_float("shutterclose", 1);
        // (shutterclose <= shutteropen is an error of create_sensor: the shutter would never open.)
        scene_->accelerator.set_shutter(scene_->shutter_open, scene_->shutter_close);
        if (!c.motion.animated) return;
        scene_->camera_motion = CameraMotion(AnimatedTransform(
            c.camera_from_world.inverse(), c.motion.start_time, c.motion.end.inverse(), c.motion.end_time));
        scene_->has_motion = true;
    }

    // A moving shape (pbrt-v4's animated shape): built in object space as a prototype of its own and
    // placed by its moving transform, as pbrt-v4's AnimatedPrimitive does.
    bool add_moving_shape(const ShapeDesc& s) {
        if (s.area_light >= 0) return add_moving_emitter(s);
        scene_->accelerator.add_moving_instance(moving_prototype(s), motion_of(s));
        scene_->has_motion = true;
        return true;
    }

    // A moving emitter (pbrt-v4 rejects it): traced as any moving shape, its lights (MovingAreaLight) sample
    // its shape at the start pose, built here too, and carry the samples to where the traced shape is at
    // their time.
    struct MovingEmitter {
        std::vector<const AreaShape*> start_shapes; // in the order add_shape makes the primitives' lights
        std::size_t next = 0;
        Transform start_from_object;
        float start_time = 0;
        std::vector<MovingAreaLight*> lights;
    };
    MovingEmitter* moving_emitter_ = nullptr; // while a moving emitter's prototype is built

    bool add_moving_emitter(const ShapeDesc& s) {
        ShapeDesc start = s;
        start.motion = {};
        std::optional<ShapeGeometry> g =
            create_shape(start, textures_, scene_->request.displacement_edge_scale);
        if (!g) return true; // removed (alpha 0) or reported
        MovingEmitter emitter;
        emitter.start_from_object = s.world_from_object;
        emitter.start_time = s.motion.start_time;
        if (g->mesh) {
            for (std::uint32_t t = 0; t < g->mesh->triangle_count(); ++t) {
                scene_->light_shapes.push_back(std::make_unique<TriangleShape>(g->mesh.get(), t));
                emitter.start_shapes.push_back(scene_->light_shapes.back().get());
            }
            scene_->light_meshes.push_back(std::move(g->mesh));
        }
        if (g->patches) {
            for (std::uint32_t i = 0; i < g->patches->patch_count(); ++i) {
                scene_->light_shapes.push_back(std::make_unique<BilinearPatchShape>(g->patches.get(), i));
                emitter.start_shapes.push_back(scene_->light_shapes.back().get());
            }
            scene_->light_patches.push_back(std::move(g->patches));
        }
        if (g->analytic) {
            emitter.start_shapes.push_back(g->analytic.get());
            scene_->light_shapes.push_back(std::move(g->analytic));
        }
        moving_emitter_ = &emitter;
        std::uint32_t prototype = moving_prototype(s);
        moving_emitter_ = nullptr;
        const AnimatedTransform motion = motion_of(s);
        std::uint32_t instance = scene_->accelerator.add_moving_instance(prototype, motion);
        for (MovingAreaLight* l : emitter.lights) l->set_motion(&scene_->accelerator, instance);
        scene_->has_motion = true;
        if (emitter.next != emitter.start_shapes.size())
            diag_.unsupported(s.loc, "a moving area light's shape differs between its start pose and its "
                                     "object space: some of its parts do not emit");
        // R(t) = M(t) M0⁻¹ keeps areas when the decomposed scale is the same at both ends of the motion;
        // otherwise the light is still exact (MovingAreaLight carries its densities through R(t)), but
        // "power" sets its radiance by its area at the start pose.
        const Matrix3d s0 = decompose(motion.start().matrix()).scale,
                       s1 = decompose(motion.end().matrix()).scale;
        double scale = 0, change = 0;
        for (int i = 0; i < 9; ++i)
            scale = std::max(scale, std::abs(s0[i])), change = std::max(change, std::abs(s1[i] - s0[i]));
        if (change > 1e-5 * scale && desc_.area_lights.at(s.area_light).params.has("power"))
            diag_.unsupported(s.loc, "a moving area light whose motion changes its size: its \"power\" sets "
                                     "its radiance by its area at the start of the motion");
        return true;
    }

    // An emitting primitive's light (shape: the primitive where it is traced): a still light, or while a
    // moving emitter is built, the moving light over the primitive's start-pose shape.
    std::unique_ptr<Light> make_emitter(const AreaEmission& e, const AreaShape* shape, float area,
                                        const FloatTexture* alpha) {
        if (!moving_emitter_) {
            auto l = e.make_light(shape, area);
            l->set_alpha(alpha);
            return l;
        }
        MovingEmitter& m = *moving_emitter_;
        if (m.next >= m.start_shapes.size()) return nullptr;
        const AreaShape* start = m.start_shapes[m.next++];
        auto still = e.make_light(start, start->area());
        still->set_alpha(alpha);
        auto l = std::make_unique<MovingAreaLight>(std::move(still), m.start_from_object, m.start_time);
        m.lights.push_back(l.get());
        return l;
    }

    static AnimatedTransform motion_of(const ShapeDesc& s) {
        return AnimatedTransform(s.world_from_object, s.motion.start_time, s.motion.end, s.motion.end_time);
    }

    // The prototype of a moving shape: the shape in its object space.
    std::uint32_t moving_prototype(const ShapeDesc& s) {
        ShapeDesc still = s;
        still.world_from_object = Transform();
        still.motion = {};
        // The orientation a handedness-swapping transform would have flipped (create_shape) is kept.
        still.reverse_orientation = s.reverse_orientation != s.world_from_object.swaps_handedness();
        std::uint32_t id = scene_->accelerator.begin_prototype();
        add_shape(still);
        scene_->accelerator.end_prototype();
        // What the copy read, the shape read (the unused-parameter report looks at the shape).
        const auto& read = still.params.params();
        const auto& own = s.params.params();
        for (std::size_t i = 0; i < read.size() && i < own.size(); ++i)
            own[i].used = own[i].used || read[i].used;
        return id;
    }

    // A shape's geometry into the accelerator with its material; an emitting shape gets one light per
    // triangle or bilinear patch (pbrt-v4) or one for the whole analytic shape, `power` normalised by the
    // exact area.
    void add_shape(const ShapeDesc& s) {
        if (s.motion.animated && add_moving_shape(s)) return;
        std::optional<ShapeGeometry> g = create_shape(s, textures_, scene_->request.displacement_edge_scale);
        if (!g) return;
        std::optional<AreaEmission> e;
        if (s.area_light >= 0) e = create_area_emission(desc_.area_lights.at(s.area_light), diag_);
        const Material* material = material_of(s.material, s.loc);
        const MediumInterface* mi = medium_interface_of(s, material);
        if (g->curves) {
            if (e)
                diag_.unsupported(s.loc,
                                  "an area light on a curve is ignored (pbrt-v4 cannot sample curves)");
            scene_->accelerator.add_curves(std::move(g->curves), material, mi, g->alpha);
            return;
        }
        if (g->mesh) {
            std::vector<const Light*> tri_lights;
            if (e) {
                for (std::uint32_t t = 0; t < g->mesh->triangle_count(); ++t) {
                    scene_->light_shapes.push_back(std::make_unique<TriangleShape>(g->mesh.get(), t));
                    auto light = make_emitter(*e, scene_->light_shapes.back().get(),
                                              g->mesh->triangle_area(t), g->alpha);
                    if (!light) {
                        tri_lights.push_back(nullptr);
                        continue;
                    }
                    set_light_media(*light, s, mi);
                    tri_lights.push_back(light.get());
                    scene_->lights.push_back(std::move(light));
                }
            }
            scene_->accelerator.add_mesh(std::move(g->mesh), material, std::move(tri_lights), g->alpha, mi);
            if (!g->patches) return; // a plymesh may hold both triangles and quads
        }
        if (g->patches) {
            std::vector<const Light*> patch_lights;
            for (std::uint32_t i = 0; e && i < g->patches->patch_count(); ++i) {
                scene_->light_shapes.push_back(std::make_unique<BilinearPatchShape>(g->patches.get(), i));
                const AreaShape* shape = scene_->light_shapes.back().get();
                auto light = make_emitter(*e, shape, shape->area(), g->alpha);
                if (!light) {
                    patch_lights.push_back(nullptr);
                    continue;
                }
                set_light_media(*light, s, mi);
                patch_lights.push_back(light.get());
                scene_->lights.push_back(std::move(light));
            }
            scene_->accelerator.add_patches(std::move(g->patches), material, std::move(patch_lights),
                                            g->alpha, mi);
            return;
        }
        const Light* light = nullptr;
        if (e) {
            if (auto l = make_emitter(*e, g->analytic.get(), g->analytic->area(), g->alpha)) {
                set_light_media(*l, s, mi);
                light = l.get();
                scene_->lights.push_back(std::move(l));
            }
        }
        scene_->accelerator.add_shape(std::move(g->analytic), material, light, false, mi);
    }

    void add_light(const LightDesc& l) {
        if (auto light = make_light(l, diag_)) {
            light->medium = medium_named(l.medium, l.medium_loc);
            scene_->lights.push_back(std::move(light));
        }
    }

    // An area light's media: its shape's interface, or (inside and outside the same) that medium.
    void set_light_media(Light& light, const ShapeDesc& s, const MediumInterface* mi) {
        light.medium_interface = mi;
        if (!mi) light.medium = medium_named(s.outside_medium, s.medium_loc);
    }

    // pbrt's ObjectBegin/ObjectInstance: each definition is built once, in its own space, as an Embree
    // prototype; each use is an Embree instance of it (memory does not grow with the number of uses).
    // Area lights in instances are ignored, as pbrt-v4 does. A moving shape of a definition (pbrt-v4's
    // animated shape of the instance) is a prototype of its own that each use places by the use's
    // transform times the shape's moving one, at the ray's time (Embree instances one level deep).
    void add_instances() {
        struct Definition {
            std::uint32_t still;
            std::vector<std::pair<std::uint32_t, AnimatedTransform>> moving;
        };
        std::unordered_map<std::string, Definition> prototypes;
        for (const InstanceUse& use : desc_.instance_uses) {
            auto it = desc_.instances.find(use.name);
            if (it == desc_.instances.end())
                throw Error(use.loc, fmt::format("undefined object \"{}\" in ObjectInstance", use.name));
            if (!use.world_from_instance.matrix().is_finite())
                throw Error(use.loc, "instance transform is not finite");
            auto p = prototypes.find(use.name);
            if (p == prototypes.end()) {
                Definition d;
                std::vector<ShapeDesc> moving;
                d.still = scene_->accelerator.begin_prototype();
                for (const ShapeDesc& shape : it->second.shapes) {
                    ShapeDesc copy = shape;
                    if (copy.area_light >= 0) {
                        diag_.unsupported(shape.loc,
                                          "area lights in object instances are ignored (as in pbrt-v4)");
                        copy.area_light = -1;
                    }
                    if (copy.motion.animated)
                        moving.push_back(std::move(copy));
                    else
                        add_shape(copy);
                }
                scene_->accelerator.end_prototype();
                for (const ShapeDesc& shape : moving)
                    d.moving.emplace_back(moving_prototype(shape), motion_of(shape));
                p = prototypes.emplace(use.name, std::move(d)).first;
            }
            const Definition& d = p->second;
            AnimatedTransform outer(use.world_from_instance);
            if (use.motion.animated) {
                outer = AnimatedTransform(use.world_from_instance, use.motion.start_time, use.motion.end,
                                          use.motion.end_time);
                scene_->accelerator.add_moving_instance(d.still, outer);
                scene_->has_motion = true;
            } else {
                scene_->accelerator.add_instance(d.still, use.world_from_instance);
            }
            for (const auto& [id, inner] : d.moving) {
                scene_->accelerator.add_moving_instance(id, outer, inner);
                scene_->has_motion = true;
            }
        }
    }

    const SceneDesc& desc_;
    Diagnostics diag_;
    std::unique_ptr<Scene> scene_;
    TextureParams textures_;
    std::vector<const Material*> materials_;
    std::unordered_map<std::string, const Material*> named_;
    const Material* default_material_ = nullptr;
    struct NamedMedium {
        const Medium* medium;
        std::size_t report; // index into scene_->medium_reports
    };
    std::map<std::string, NamedMedium> media_;
    std::map<const Material*, std::size_t> interior_reports_; // subsurface media, into medium_reports
};

} // namespace

std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const BuildOptions& options) {
    return Builder(desc, options).build();
}

} // namespace illum

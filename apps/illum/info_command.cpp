// `illum info scene.pbrt`: what a scene holds (shapes, triangles, materials, textures, lights, camera,
// film, sampler, integrator), every warning, and last the unsupported features it uses (grouped by kind,
// with positions; "none" when there are none), without rendering. The scene is built (meshes loaded) so
// that triangle counts and build warnings are those a render would see.
#include <algorithm>
#include <fmt/core.h>
#include <map>
#include <memory>

#include "commands.h"
#include "illum/scene/build.h"
#include "scene_loading.h"

namespace illum::cli {

namespace {

struct InfoArgs {
    std::string scene;
    bool strict = false;
};

std::string counts(const std::map<std::string, int>& m) {
    std::string s;
    for (const auto& [k, v] : m) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", v, k);
    return s.empty() ? "none" : s;
}

// The closing section: every unsupported or approximated feature the scene uses, one line per kind with
// its count and every position, or "none" (issue 13's target).
void print_unsupported(const std::vector<UnsupportedUse>& uses) {
    std::vector<UnsupportedKind> kinds = group_by_kind(uses);
    if (kinds.empty()) {
        fmt::print("unsupported features: none\n");
        return;
    }
    fmt::print("unsupported features: {} kind{}, {} use{}\n", kinds.size(), kinds.size() == 1 ? "" : "s",
               uses.size(), uses.size() == 1 ? "" : "s");
    for (const UnsupportedKind& k : kinds) {
        std::string at;
        for (const SourceLocation& l : k.uses)
            if (!l.file.empty()) at += (at.empty() ? "" : ", ") + l.to_string();
        fmt::print("  {} x{}{}\n", k.what, k.uses.size(), at.empty() ? "" : " at " + at);
    }
}

void run(const InfoArgs& args) {
    SceneDesc desc = load_scene_desc(args.scene, args.strict);
    BuildOptions opt;
    opt.strict = args.strict;
    std::unique_ptr<Scene> scene = build_scene(desc, opt);

    std::map<std::string, int> shapes, materials, textures, lights;
    int emitting = 0;
    for (const ShapeDesc& s : desc.shapes) {
        ++shapes[s.type];
        if (s.area_light >= 0) ++emitting;
    }
    int instanced = 0;
    for (const auto& [name, def] : desc.instances) instanced += int(def.shapes.size());
    for (const MaterialDesc& m : desc.materials)
        ++materials[m.name.empty() ? m.type : m.params.get_string("type", m.type)];
    for (const TextureDesc& t : desc.textures) ++textures[t.value_type + " " + t.type];
    for (const LightDesc& l : desc.lights) ++lights[l.type];

    const EntityDesc& c = desc.camera;
    fmt::print("scene       {}\n", desc.filename.empty() ? "(built-in Cornell box)" : desc.filename);
    fmt::print("camera      {}", c.type.empty() ? "perspective" : c.type);
    if (c.type == "perspective" || c.type.empty()) fmt::print(", fov {}", c.params.get_float("fov", 90));
    if (c.params.get_float("lensradius", 0) > 0)
        fmt::print(", lens radius {}, focal distance {}", c.params.get_float("lensradius", 0),
                   c.params.get_float("focaldistance", 1e6f));
    fmt::print("\nfilm        {} {}x{}{}\n", desc.film.type, scene->width, scene->height,
               scene->request.output.empty() ? "" : ", file " + scene->request.output);
    fmt::print("filter      {}\n", desc.filter.type);
    fmt::print("sampler     {} (rendered as {}), {} spp\n", desc.sampler.type, scene->request.sampler,
               scene->request.spp);
    fmt::print("integrator  {} (rendered as {}), max depth {}\n", desc.integrator.type,
               scene->request.integrator, scene->request.max_depth);
    fmt::print("shapes      {} ({}); {} emitting\n", desc.shapes.size(), counts(shapes), emitting);
    if (!desc.instances.empty())
        fmt::print("instances   {} definitions with {} shapes, {} uses\n", desc.instances.size(), instanced,
                   desc.instance_uses.size());
    fmt::print("triangles   {} (stored once per instanced object)\n", scene->accelerator.triangle_count());
    if (std::size_t n = scene->accelerator.instance_count()) fmt::print("instances   {}\n", n);
    fmt::print("geometries  {}\n", scene->accelerator.geometry_count());
    fmt::print("materials   {} ({})\n", desc.materials.size(), counts(materials));
    fmt::print("textures    {} ({})\n", desc.textures.size(), counts(textures));
    fmt::print("lights      {} ({}); {} area-light primitives; {} lights in all\n", desc.lights.size(),
               counts(lights), scene->lights.size() - std::min(scene->lights.size(), desc.lights.size()),
               scene->lights.size());
    if (!scene->medium_reports.empty()) {
        fmt::print("media       {}{}\n", scene->medium_reports.size(),
                   scene->camera_medium ? fmt::format(" (the camera is in \"{}\")", desc.camera.medium) : "");
        for (const Scene::MediumReport& m : scene->medium_reports) {
            fmt::print("  medium {}: {}, {:.1f} KiB\n", m.name.front() == '(' ? m.name : "\"" + m.name + "\"",
                       m.type, double(m.bytes) / 1024);
            if (m.bounded_by.empty()) fmt::print("    bounded by no shape\n");
            for (const std::string& b : m.bounded_by) fmt::print("    {}\n", b);
        }
    }
    fmt::print("warnings    {}\n", scene->warnings.size());
    for (const auto& w : scene->warnings) fmt::print("warning: {}\n", w);
    print_unsupported(scene->unsupported);
}

} // namespace

void add_info_command(CLI::App& app) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* cmd =
        app.add_subcommand("info", "Print what a scene holds and its warnings, without rendering");
    cmd->add_option("scene", args->scene, "Scene file (.pbrt); omit for the built-in Cornell box");
    cmd->add_flag("--strict", args->strict, "Unsupported scene features are errors, not warnings");
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli

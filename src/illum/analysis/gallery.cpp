#include "illum/analysis/gallery.h"

#include <cmath>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/registry.h"
#include "illum/bsdf/shared_bxdf_material.h"
#include "illum/geometry/sphere.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/uniform_environment_light.h"

namespace illum {

std::vector<GalleryEntry> gallery_entries() {
    std::vector<GalleryEntry> entries;
    for (const ModelSpec& m : bxdf_models()) {
        GalleryEntry e{m.name, {}};
        if (m.name == "merl") e.params["file"] = "synthetic:0.2"; // no measured file ships: a GGX-gold table
        if (m.name == "measured") e.params["filename"] = "synthetic:0.2"; // an RGL table of a GGX conductor
        entries.push_back(e);
    }
    return entries;
}

namespace {

std::unique_ptr<TriangleMesh> quad(Point3f c, Vector3f u, Vector3f v) {
    auto m = std::make_unique<TriangleMesh>();
    m->p = {c - u - v, c + u - v, c + u + v, c - u + v};
    m->uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m->indices = {0, 1, 2, 0, 2, 3};
    m->finalize();
    return m;
}

} // namespace

std::unique_ptr<Scene> make_gallery_scene(int width, int height) {
    auto scene = std::make_unique<Scene>();
    Scene& s = *scene;
    s.width = width;
    s.height = height;
    s.filter = make_filter("gaussian", {1.5f, 1.5f});
    s.request.max_depth = 12;

    auto entries = gallery_entries();
    const int columns = 6, rows = int((entries.size() + columns - 1) / columns);
    const float spacing = 1.1f, radius = 0.45f;

    // Floor: a grey checkerboard (z up), the spheres rest on it.
    s.color_textures.push_back(std::make_unique<ConstantColorTexture>(Color3(0.35f)));
    s.color_textures.push_back(std::make_unique<ConstantColorTexture>(Color3(0.6f)));
    s.color_textures.push_back(std::make_unique<CheckerboardColorTexture>(s.color_textures[0].get(),
                                                                          s.color_textures[1].get(), 12, 12));
    s.materials.push_back(std::make_unique<DiffuseMaterial>(s.color_textures.back().get()));
    s.accelerator.add_mesh(quad({0, 0, 0}, {12, 0, 0}, {0, 12, 0}), s.materials.back().get(), {});

    for (std::size_t i = 0; i < entries.size(); ++i) {
        int col = int(i) % columns, row = int(i) / columns;
        // Row 0 at the back, so the image reads like the list: left to right, top to bottom. The camera
        // looks along +y with +z up, so by pbrt's LookAt image right is world -x.
        Point3f c{((columns - 1) / 2.0f - col) * spacing, ((rows - 1) / 2.0f - row) * spacing * 1.15f,
                  radius};
        const ModelSpec& spec = find_bxdf_model(entries[i].model);
        auto bxdf = make_bxdf(entries[i].model, entries[i].params);
        // The albedo pass shows the directional albedo at normal incidence (Monte Carlo: it covers delta
        // lobes too).
        AlbedoEstimate a = directional_albedo(*bxdf, {0, 0, 1}, spec.delta, 16, 4096, 1);
        Color3 albedo(float(a.mc[0]), float(a.mc[1]), float(a.mc[2]));
        s.materials.push_back(std::make_unique<SharedBxDFMaterial>(std::move(bxdf), albedo));
        s.accelerator.add_shape(std::make_unique<SphereShape>(c, radius, false), s.materials.back().get(),
                                nullptr);
    }

    // A one-sided rectangular light above and in front, facing down towards the spheres.
    auto light_mesh = quad({0, -3.0f, 5.0f}, {2.5f, 0, 0}, {0, 1.2f, 0.6f});
    std::swap(light_mesh->indices[1], light_mesh->indices[2]);
    std::swap(light_mesh->indices[4], light_mesh->indices[5]);
    light_mesh->finalize(); // normal now faces down
    s.color_textures.push_back(std::make_unique<ConstantColorTexture>(Color3(0.0f)));
    s.materials.push_back(std::make_unique<DiffuseMaterial>(s.color_textures.back().get()));
    std::vector<const Light*> tri_lights;
    for (std::uint32_t t = 0; t < light_mesh->triangle_count(); ++t) {
        s.light_shapes.push_back(std::make_unique<TriangleShape>(light_mesh.get(), t));
        s.lights.push_back(std::make_unique<DiffuseAreaLight>(s.light_shapes.back().get(),
                                                              Emission(Color3(6.0f, 5.8f, 5.4f)), false));
        tri_lights.push_back(s.lights.back().get());
    }
    s.accelerator.add_mesh(std::move(light_mesh), s.materials.back().get(), std::move(tri_lights));
    s.lights.push_back(std::make_unique<UniformEnvironmentLight>(Emission(Color3(0.25f, 0.28f, 0.33f))));

    // Camera: from the front and above, looking at the grid.
    Transform camera_from_world = Transform::look_at({0, -7.6f, 4.6f}, {0, 0.1f, 0.3f}, {0, 0, 1});
    s.camera = std::make_unique<PerspectiveCamera>(camera_from_world.inverse(), width, height, 30.0f);
    s.finalize();
    return scene;
}

} // namespace illum

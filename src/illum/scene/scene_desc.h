// SceneDesc: what a scene file says, as plain data with no behaviour (DESIGN.md §1). Parsers (pbrt-v4,
// built-in scenes) produce it; build() turns it into runtime objects once. Every entity keeps its
// source position so later errors can still name file:line:column.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "illum/math/transform.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"
#include "illum/util/error.h"

namespace illum {

struct InstanceDefinition {
    std::string name;
    // world_from_object is the full CTM at the Shape, as pbrt-v4 keeps it (including any transform in
    // effect at ObjectBegin); a use places the shape at world_from_instance * world_from_object.
    std::vector<ShapeDesc> shapes;
    SourceLocation loc;
};

struct InstanceUse {
    std::string name;
    Transform world_from_instance;
    TransformMotion motion; // world_from_instance at the end time, when the instance moves
    SourceLocation loc;
};

struct SceneDesc {
    std::string filename; // the top-level file, "" for a built-in scene
    std::string base_dir; // relative file names in parameters resolve against this

    CameraDesc camera;
    EntityDesc film{"rgb", {}, {}};
    EntityDesc sampler{"zsobol", {}, {}};
    EntityDesc filter{"gaussian", {}, {}};
    EntityDesc integrator{"volpath", {}, {}};
    ParamSet options;                 // Option directives (render/scene_options.h reads them)
    std::string color_space = "srgb"; // the last ColorSpace directive

    std::vector<MaterialDesc> materials; // anonymous and named; named ones are also in named_materials
    std::map<std::string, int> named_materials;
    std::vector<TextureDesc> textures;
    std::map<std::string, int> float_textures, spectrum_textures; // name -> index into textures
    std::vector<ShapeDesc> shapes;
    std::vector<EntityDesc> area_lights; // AreaLightSource entities referenced by shapes
    std::vector<LightDesc> lights;
    std::map<std::string, InstanceDefinition> instances;
    std::vector<InstanceUse> instance_uses;
    std::map<std::string, MediumDesc> media; // MakeNamedMedium

    std::vector<std::string> warnings;       // recognised but unsupported features, with positions
    std::vector<UnsupportedUse> unsupported; // the same, structured (illum info lists them)

    // Overrides the film's resolution (the command line's --resolution, tests rendering smaller).
    void set_film_resolution(int width, int height) {
        for (auto [name, v] : {std::pair{"xresolution", width}, std::pair{"yresolution", height}}) {
            Param p;
            p.type = ParamType::Integer;
            p.name = name;
            p.numbers = {double(v)};
            film.params.add(p);
        }
    }
};

} // namespace illum

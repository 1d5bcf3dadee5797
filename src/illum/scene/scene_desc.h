// SceneDesc: what a scene file says, as plain data with no behaviour (DESIGN.md §1). Parsers (pbrt-v4,
// built-in scenes) produce it; build() turns it into runtime objects once. Every entity keeps its
// source position so later errors can still name file:line:column.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "illum/math/transform.h"
#include "illum/scene/param_set.h"
#include "illum/util/error.h"

namespace illum {

struct EntityDesc {
    std::string type; // "perspective", "diffuse", "trianglemesh", ...
    ParamSet params;
    SourceLocation loc;
};

struct CameraDesc : EntityDesc {
    Transform camera_from_world; // pbrt's CTM at the Camera directive
    std::string medium;          // the outside medium current at the Camera directive ("" for none)
};

struct MaterialDesc : EntityDesc {
    std::string name; // empty for an anonymous Material
};

struct TextureDesc : EntityDesc {
    std::string name;
    std::string value_type; // "float" or "spectrum"
    Transform world_from_texture;
};

// Which material a shape uses: an index into SceneDesc::materials, or a name resolved at build time.
// Neither (index -1, empty name) means pbrt-v4's default material: "diffuse" with reflectance 0.5.
struct MaterialRef {
    int index = -1;
    std::string name;
};

struct ShapeDesc : EntityDesc {
    Transform world_from_object;
    bool reverse_orientation = false;
    MaterialRef material;
    int area_light = -1; // index into SceneDesc::area_lights, -1 when the shape does not emit
    std::string inside_medium, outside_medium;
};

struct LightDesc : EntityDesc {
    Transform world_from_light;
    std::string medium; // the outside medium current at the LightSource directive
};

// MakeNamedMedium: recorded as given; the renderer may not support participating media.
struct MediumDesc : EntityDesc {
    std::string name;
    Transform world_from_medium;
};

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
    std::map<std::string, std::string> options; // Option directives: name -> value as text
    std::string color_space = "srgb";           // the last ColorSpace directive

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

    std::vector<std::string> warnings; // recognised but unsupported features, with positions

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

// What a scene file says about one entity (a camera, a shape, a light...): its type, its parameters as
// written and its position, plus what the directive's graphics state adds. Plain data (DESIGN.md §1): the
// parsers fill it, each entity kind's create function reads it, so it sits below every module that
// creates something from a scene file.
#pragma once

#include <string>

#include "illum/math/transform.h"
#include "illum/param/param_set.h"
#include "illum/util/error.h"

namespace illum {

// pbrt-v4's moving transforms: the current transform at the end time (set under ActiveTransform EndTime)
// and the times of TransformTimes, kept when the end transform differs from the start one (the entity's
// own transform field is the start one).
struct TransformMotion {
    bool animated = false;
    Transform end;
    double start_time = 0, end_time = 1;
};

struct EntityDesc {
    std::string type; // "perspective", "diffuse", "trianglemesh", ...
    ParamSet params;
    SourceLocation loc;
};

struct CameraDesc : EntityDesc {
    Transform camera_from_world; // pbrt's CTM at the Camera directive
    TransformMotion motion;      // camera_from_world at the end time, when the camera moves
    std::string medium;          // the outside medium current at the Camera directive ("" for none)
    SourceLocation medium_loc;   // the MediumInterface directive that named it
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
    TransformMotion motion; // world_from_object at the end time, when the shape moves
    bool reverse_orientation = false;
    MaterialRef material;
    int area_light = -1; // index into SceneDesc::area_lights, -1 when the shape does not emit
    std::string inside_medium, outside_medium;
    SourceLocation medium_loc; // the MediumInterface directive that named them
};

struct LightDesc : EntityDesc {
    Transform world_from_light;
    std::string medium; // the outside medium current at the LightSource directive
    SourceLocation medium_loc;
};

// MakeNamedMedium: the medium's parameters and the transform current at the directive (medium space).
struct MediumDesc : EntityDesc {
    std::string name;
    Transform world_from_medium;
};

} // namespace illum

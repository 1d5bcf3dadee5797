// Materials from a scene file (pbrt-v4's Material and MakeNamedMaterial): pbrt-v4's own types with their
// parameters, and every model of the registry (`illum brdf list`) by its name, its parameters checked
// against the model's spec and resolved to slots (constants or textures) once.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "illum/bsdf/material.h"
#include "illum/param/entity.h"
#include "illum/texture/texture_params.h"

namespace illum {

struct MaterialContext {
    TextureParams& textures;
    std::vector<std::unique_ptr<Material>>& owned;                 // where created materials live
    const std::unordered_map<std::string, const Material*>& named; // earlier named materials (for "mix")
};

// The material `type` (a Material's type, or a named material's "string type") made from `m`'s
// parameters. Throws illum::Error at the entity or parameter for an unknown type or a bad value.
const Material* create_material(const EntityDesc& m, const std::string& type, MaterialContext& ctx);

} // namespace illum

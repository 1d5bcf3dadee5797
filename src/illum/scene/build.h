// build(): SceneDesc -> Scene, once. Every error names the entity's file:line:column.
#pragma once

#include <memory>

#include "illum/render/scene.h"
#include "illum/scene/scene_desc.h"

namespace illum {

struct BuildOptions {
    bool strict = false; // recognised but unsupported features are errors instead of warnings
};

std::unique_ptr<Scene> build_scene(const SceneDesc& desc, const BuildOptions& options = {});

} // namespace illum

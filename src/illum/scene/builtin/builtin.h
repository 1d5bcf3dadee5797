// Scenes built into illum, for `illum render` with no scene file and for tests.
#pragma once

#include "illum/scene/scene_desc.h"

namespace illum {

// B. Bitterli's Cornell box (1024x1024, 64 spp, path tracing up to depth 65): illum's default scene.
SceneDesc builtin_cornell_box();

} // namespace illum

// Lights from their scene description (pbrt-v4's LightSource directive): one place that knows each
// light type's parameters, used by the scene builder.
#pragma once

#include <memory>
#include <string>

#include "illum/light/light.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

// The light for a LightSource; nullptr when the type is recognised but skipped (after a warning in
// `diag`) or its image cannot be read (recorded in `diag`, so every missing file of a scene is reported
// together). Throws illum::Error naming the position for an unknown type or a bad parameter.
std::unique_ptr<Light> make_light(const LightDesc& desc, Diagnostics& diag);

} // namespace illum

// Lights from their scene description (pbrt-v4's LightSource directive): one place that knows each
// light type's parameters, used by the scene builder.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "illum/light/light.h"
#include "illum/param/entity.h"

namespace illum {

struct LightFactoryContext {
    // Reports a recognised but unsupported feature (a warning, or an error under --strict).
    std::function<void(const SourceLocation&, const std::string&)> unsupported;
};

// The light for a LightSource; nullptr when the type is recognised but skipped (after a warning).
// Throws illum::Error naming the position for an unknown type or a bad parameter.
std::unique_ptr<Light> make_light(const LightDesc& desc, const LightFactoryContext& ctx);

} // namespace illum

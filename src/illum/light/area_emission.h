// pbrt-v4's AreaLightSource "diffuse": what a shape emits. L (default: the colour space's illuminant,
// luminance 1) times `scale`; a spectrum L is normalised to luminance 1 first ("scale /=
// SpectrumToPhotometric(L)"), an RGB L is not (pbrt-v4 normalises only its illuminant part, D65 of
// luminance 1). With `power` P > 0 the radiance is further multiplied by P / (π · (twosided ? 2 : 1) ·
// area), where area is that of one primitive (pbrt-v4 makes one light per triangle, so each triangle of a
// mesh emits P).
#pragma once

#include "illum/param/entity.h"
#include "illum/radiometry/emission.h"
#include "illum/radiometry/quantity.h"
#include "illum/util/diagnostics.h"

namespace illum {

struct AreaEmission {
    Emission radiance;
    bool two_sided = false;
    float power = -1;
    // The radiance of a primitive of the given area [m²].
    Emission for_area(float area) const;
};

AreaEmission create_area_emission(const EntityDesc& area_light, Diagnostics& diag);

} // namespace illum

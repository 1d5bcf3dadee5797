// pbrt-v4's AreaLightSource "diffuse": what a shape emits. L (default: the colour space's illuminant,
// luminance 1) times `scale`; a spectrum L is normalised to luminance 1 first ("scale /=
// SpectrumToPhotometric(L)"), an RGB L is not (pbrt-v4 normalises only its illuminant part, D65 of
// luminance 1). With `power` P > 0 the radiance is further multiplied by P / (π · (twosided ? 2 : 1) ·
// area), where area is that of one primitive (pbrt-v4 makes one light per triangle, so each triangle of a
// mesh emits P).
// With "filename" (not together with "L", as in pbrt-v4) the radiance is the image's RGB, looked up by the
// surface's uv (DiffuseAreaLight), times `scale`; `power` then also divides by the image's mean luminance
// (pbrt-v4's k_e: the mean over texels of the RGB's luminance).
#pragma once

#include <memory>

#include "illum/image/image.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/param/entity.h"
#include "illum/radiometry/emission.h"
#include "illum/radiometry/quantity.h"
#include "illum/util/diagnostics.h"

namespace illum {

struct AreaEmission {
    Emission radiance; // with an image: its grey scale
    bool two_sided = false;
    float power = -1;
    std::shared_ptr<const Image> image;
    double image_mean_luminance = 0;
    // The radiance (or the image's scale) of a primitive of the given area [m²].
    Emission for_area(float area) const;
    // The light of one primitive of the given area.
    std::unique_ptr<DiffuseAreaLight> make_light(const AreaShape* shape, float area) const;
};

// A missing image file is recorded in `diag` (the emission is then black; the build reports it).
AreaEmission create_area_emission(const EntityDesc& area_light, Diagnostics& diag);

} // namespace illum

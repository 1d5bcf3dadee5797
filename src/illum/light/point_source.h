// Next-event estimation towards a point source (point, spot, goniometric and projection lights): the
// direction to the source is the only one (a delta, probability 1), and the biradiance is I(-wi) / r², the
// intensity the source sends towards the shading point over the squared distance (PBR 4th ed. §12.1).
#pragma once

#include <cmath>
#include <optional>

#include "illum/light/light.h"

namespace illum {

// `intensity(w)`: the source's intensity in the direction w of travel (unit, away from the source).
template <class IntensityTowards>
std::optional<LightLiSample> point_source_li(Point3f source, Point3f p, IntensityTowards&& intensity) {
    Vector3f d = source - p;
    float d2 = length_squared(d);
    if (d2 == 0) return std::nullopt;
    Vector3f wi = d / std::sqrt(d2);
    Intensity3 i = intensity(-wi);
    if (i.is_black()) return std::nullopt;
    return LightLiSample{wi, {}, biradiance(i, d2), SolidAnglePdf(1), source, {}, {}, false};
}

} // namespace illum

#include "illum/medium/subsurface_coefficients.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "illum/medium/measured_media.h"

namespace illum {

namespace {

Color3 clamp_zero(Color3 c) { return {std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)}; }

} // namespace

std::optional<SubsurfaceCoefficients> subsurface_from_name(std::string_view name, float scale) {
    std::optional<MeasuredMedium> m = measured_medium(name);
    if (!m) return std::nullopt;
    return subsurface_from_sigma(m->sigma_a, m->sigma_s, scale);
}

SubsurfaceCoefficients subsurface_from_sigma(Color3 sigma_a, Color3 sigma_s, float scale) {
    return {clamp_zero(sigma_a * scale), clamp_zero(sigma_s * scale)};
}

SubsurfaceCoefficients subsurface_default(float scale) {
    return subsurface_from_sigma(kSubsurfaceDefaultSigmaA, kSubsurfaceDefaultSigmaS, scale);
}

SubsurfaceCoefficient subsurface_from_reflectance(float reflectance, float mfp, float scale,
                                                  const EffectiveAlbedoTable& table) {
    float r = std::isnan(reflectance) ? 0.0f : std::clamp(reflectance, 0.0f, 1.0f);
    float path = std::max(scale * mfp, 0.0f);
    float albedo = albedo_from_effective_reflectance(r, table);
    if (!(path > 0)) { // pbrt-v4 divides by zero here (0 / 0 = NaN when α is 0 or 1)
        constexpr float inf = std::numeric_limits<float>::infinity();
        return {albedo < 1 ? inf : 0.0f, albedo > 0 ? inf : 0.0f};
    }
    return {(1 - albedo) / path, albedo / path};
}

SubsurfaceCoefficients subsurface_from_reflectance(Color3 reflectance, Color3 mfp, float scale,
                                                   const EffectiveAlbedoTable& table) {
    SubsurfaceCoefficients c;
    for (int i = 0; i < 3; ++i) {
        SubsurfaceCoefficient v = subsurface_from_reflectance(reflectance[i], mfp[i], scale, table);
        c.sigma_a[i] = v.sigma_a;
        c.sigma_s[i] = v.sigma_s;
    }
    return c;
}

} // namespace illum

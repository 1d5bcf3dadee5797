// Sampling shared by the models made of a glossy lobe around the half vector and a diffuse lobe
// (Cook-Torrance, Torrance-Sparrow, Ward, Blinn-Phong, the fitted lobe of MERL): with probability p_glossy
// a half vector h from the lobe, reflected about it; otherwise a cosine-weighted direction. The density of
// wi is the mixture
//     p(wi) = p_glossy p_h(h) / (4 |wo·h|) + (1 - p_glossy) |cos θi| / π,
// 1/(4 |wo·h|) being the Jacobian of reflection about h (Walter et al. 2007, eq. 14).
//
// A Lobe provides `Vector3f sample_wm(Vector3f wo, Point2f u)` (a half vector on the +z side) and
// `float pdf_wm(Vector3f wo, Vector3f h)` (its density per steradian of h, h on the +z side).
#pragma once

#include <optional>

#include "illum/bsdf/bxdf.h"
#include "illum/math/warp.h"

namespace illum {

template <class Lobe>
float glossy_diffuse_pdf(const Lobe& lobe, float p_glossy, Vector3f wo, Vector3f wi) {
    if (!same_hemisphere(wo, wi)) return 0;
    float pd = std::abs(wi.z) * kInvPi, ps = 0;
    Vector3f h = wo + wi;
    if (length_squared(h) > 0) {
        h = normalize(h);
        if (h.z < 0) h = -h;
        float oh = abs_dot(wo, h);
        if (oh > 0) ps = lobe.pdf_wm(wo, h) / (4 * oh);
    }
    return p_glossy * ps + (1 - p_glossy) * pd;
}

// The sample of `model` (its f() and pdf() give the value and the exact mixture density).
template <class Model, class Lobe>
std::optional<BSDFSample> sample_glossy_diffuse(const Model& model, const Lobe& lobe, float p_glossy,
                                                Vector3f wo, float uc, Point2f u, TransportMode mode) {
    if (wo.z == 0) return std::nullopt;
    Vector3f wi;
    if (uc < p_glossy) {
        Vector3f h = lobe.sample_wm(wo, u);
        if (wo.z < 0) h = -h;
        wi = reflect(wo, h);
    } else {
        wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
    }
    if (!same_hemisphere(wo, wi)) return std::nullopt;
    float p = model.pdf(wo, wi, mode).value;
    if (!(p > 0)) return std::nullopt;
    return BSDFSample{wi, model.f(wo, wi, mode), SolidAnglePdf(p), kGlossyReflection};
}

} // namespace illum

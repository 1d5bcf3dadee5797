// The V-cavity microfacet BRDF shared by Torrance & Sparrow (1967) and Cook & Torrance (1982), which differ
// only in their facet distribution D:
//   f = kd/π + ks F(wo·h) D(h) G(wo, wi, h) / (4 |cos θo| |cos θi|),
// with h the half vector and G the V-cavity masking-shadowing term (vcavity_G).
#pragma once

#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"
#include "illum/radiometry/quantity.h"

namespace illum {

// D: any callable giving the facet density at a unit half vector on the +z side.
template <class Distribution>
Bsdf3 vcavity_microfacet_f(Vector3f wo, Vector3f wi, SampledSpectrum kd, SampledSpectrum ks,
                           const Fresnel& fresnel, const Distribution& D) {
    if (!same_hemisphere(wo, wi)) return {};
    float co = std::abs(wo.z), ci = std::abs(wi.z);
    Vector3f h = wo + wi;
    if (co == 0 || ci == 0 || length_squared(h) == 0) return {};
    h = normalize(h);
    if (h.z < 0) h = -h;
    Vector3f wof = wo.z < 0 ? -wo : wo, wif = wo.z < 0 ? -wi : wi;
    SampledSpectrum F = fresnel(dot(wof, h));
    float spec = D(h) * vcavity_G(wof, wif, h) / (4 * co * ci);
    return Bsdf3(kd * kInvPi + ks * F * spec);
}

} // namespace illum

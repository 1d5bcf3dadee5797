// A rough conductor: the microfacet reflection BRDF (Walter et al. 2007, eq. 20; Cook & Torrance's form
// with the 4 of Walter's derivation)
//   f(wo, wi) = D(h) G2(wo, wi) F(wo·h) / (4 |cos θo| |cos θi|),   h = normalize(wo + wi),
// with Beckmann or GGX D (anisotropic αx, αy), Smith height-correlated G2 and the exact conductor
// Fresnel term (or Schlick). Sampling: wm from the visible normals (GGX) or D cos (Beckmann), then
// wi = reflect(wo, wm) with pdf = pdf_wm / (4 |wo·wm|). Single scattering only: energy that would
// bounce between facets is lost, so albedo falls below the Fresnel reflectance as α grows.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"

namespace illum {

namespace bsdf_detail {
inline void check_alpha(const char* model, float ax, float ay) {
    ILLUM_REQUIRE(in_range(ax, 1e-3f, 2) && in_range(ay, 1e-3f, 2), model,
                  "roughness alpha must be in [0.001, 2], got " + str(ax) + (ax == ay ? "" : ", " + str(ay)));
}
} // namespace bsdf_detail

class RoughConductorBxDF final : public BxDF {
public:
    RoughConductorBxDF(MicrofacetDistribution distrib, Fresnel fresnel)
        : distrib_(distrib), fresnel_(fresnel) {
        using namespace bsdf_detail;
        check_alpha("rough-conductor", distrib.alpha_x(), distrib.alpha_y());
        SampledSpectrum e = fresnel.eta;
        ILLUM_REQUIRE(all_positive(e), "rough-conductor", "eta must be > 0, got " + str(e));
        ILLUM_REQUIRE(in_range(fresnel.k, 0, 1e4f), "rough-conductor",
                      "k must be >= 0, got " + str(fresnel.k));
    }
    std::uint8_t flags() const override { return kGlossyReflection; }
    bool isotropic() const override { return distrib_.alpha_x() == distrib_.alpha_y(); }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        float co = abs_cos_theta(wo), ci = abs_cos_theta(wi);
        if (co == 0 || ci == 0) return {};
        Vector3f h = wo + wi;
        if (length_squared(h) == 0) return {};
        h = normalize(h);
        if (h.z < 0) h = -h;
        SampledSpectrum F = fresnel_(abs_dot(wo, h));
        return Bsdf3(F * (distrib_.D(h) * distrib_.G(wo, wi) / (4 * co * ci)));
    }

    bool reads_lobe_sample() const override { return false; }

    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f u, TransportMode) const override {
        if (wo.z == 0) return std::nullopt;
        Vector3f wm = distrib_.sample_wm(wo, u);
        Vector3f wof = wo.z < 0 ? -wo : wo;
        if (dot(wof, wm) <= 0) return std::nullopt;
        Vector3f wi = reflect(wo, wm);
        if (!same_hemisphere(wo, wi)) return std::nullopt;
        // D(wm) and Λ(wo) serve the density and the value (f() would find wm again as the half vector).
        const float d = distrib_.D(wm), lambda_o = distrib_.Lambda(wo);
        const float cos_om = abs_dot(wo, wm);
        float pdf = distrib_.pdf_wm(wo, wm, d, lambda_o) / (4 * cos_om);
        if (!(pdf > 0)) return std::nullopt;
        float g = 1 / (1 + lambda_o + distrib_.Lambda(wi));
        SampledSpectrum f = fresnel_(cos_om) * (d * g / (4 * abs_cos_theta(wo) * abs_cos_theta(wi)));
        return BSDFSample{wi, Bsdf3(f), SolidAnglePdf(pdf), kGlossyReflection};
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        Vector3f h = wo + wi;
        if (length_squared(h) == 0) return SolidAnglePdf(0);
        h = normalize(h);
        if (h.z < 0) h = -h;
        return SolidAnglePdf(distrib_.pdf_wm(wo, h) / (4 * abs_dot(wo, h)));
    }

    const MicrofacetDistribution& distribution() const { return distrib_; }

private:
    MicrofacetDistribution distrib_;
    Fresnel fresnel_;
};

} // namespace illum

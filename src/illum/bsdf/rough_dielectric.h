// A rough dielectric interface (Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction
// through Rough Surfaces", eqs. 20-21). Outside +z has index 1, inside η. With η' = n_t/n_i along wi
// (η if wo is outside):
//   reflection:   f_r = F(wo·h) D(h) G2 / (4 |cos θo| |cos θi|),  h = normalize(wo + wi)
//   transmission: f_t = (1 - F(wo·h)) D(h) G2 |wi·h| |wo·h| / (|cos θo| |cos θi| (wi·h + wo·h/η')²),
//                 h = normalize(wo + η' wi) (the generalised half vector, Walter eq. 16),
// and f_t /= η'² in radiance mode, which makes f(wo,wi)/η_o² = f(wi,wo)/η_i² (generalised
// reciprocity). Sampling: wm from the visible normals, reflect with probability F, else refract;
// pdf_t = pdf_wm · |wi·h| / (wi·h + wo·h/η')² (the Jacobian of the refraction map, Walter eq. 17).
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"
#include "illum/bsdf/rough_conductor.h"

namespace illum {

class RoughDielectricBxDF final : public BxDF {
public:
    RoughDielectricBxDF(MicrofacetDistribution distrib, float eta, FresnelMode mode = FresnelMode::Exact)
        : distrib_(distrib), fresnel_{eta, mode} {
        using namespace bsdf_detail;
        check_alpha("rough-dielectric", distrib.alpha_x(), distrib.alpha_y());
        ILLUM_REQUIRE(in_range(eta, 1e-3f, 100), "rough-dielectric",
                      "eta must be in (0, 100], got " + str(eta));
    }
    std::uint8_t flags() const override { return kGlossyReflection | kGlossyTransmission; }
    bool isotropic() const override { return distrib_.alpha_x() == distrib_.alpha_y(); }
    float eta() const { return fresnel_.eta; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        float co = cos_theta(wo), ci = cos_theta(wi);
        if (co == 0 || ci == 0) return {};
        bool reflect = co * ci > 0;
        float etap = 1;
        if (!reflect) etap = co > 0 ? fresnel_.eta : 1 / fresnel_.eta;
        Vector3f wm = wi * etap + wo;
        if (length_squared(wm) == 0) return {};
        wm = normalize(wm);
        if (wm.z < 0) wm = -wm;
        // Microfacets seen from behind do not contribute.
        if (dot(wm, wi) * ci < 0 || dot(wm, wo) * co < 0) return {};
        float F = fresnel_(dot(wo, wm));
        if (reflect) return Bsdf3(SampledSpectrum(reflected(distrib_.D(wm), distrib_.G(wo, wi), F, ci, co)));
        return Bsdf3(SampledSpectrum(transmitted(distrib_.D(wm), distrib_.G(wo, wi), F, dot(wi, wm),
                                                 dot(wo, wm), etap, ci, co, mode)));
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return sample_lobes(wo, uc, u, mode, Lobes::All);
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        return pdf_lobes(wo, wi, mode, Lobes::All);
    }

    // At the sampled microfacet, reflection with probability pr / (pr + pt), pr = F and pt = 1 - F unless
    // a side is excluded.
    std::optional<BSDFSample> sample_lobes(Vector3f wo, float uc, Point2f u, TransportMode mode,
                                           Lobes lobes) const {
        if (wo.z == 0) return std::nullopt;
        Vector3f wm = distrib_.sample_wm(wo, u);
        Vector3f wof = wo.z < 0 ? -wo : wo;
        if (dot(wof, wm) <= 0) return std::nullopt;
        // F, D(wm) and Λ(wo) serve the lobe choice, the density and the value alike (f() would find the
        // same microfacet again from wo and wi).
        const float cos_om = dot(wo, wm);
        const float F = fresnel_(cos_om);
        float pr, pt;
        lobe_weights(F, lobes, &pr, &pt);
        if (!(pr + pt > 0)) return std::nullopt;
        const float d = distrib_.D(wm), lambda_o = distrib_.Lambda(wo);
        const float pdf_wm = distrib_.pdf_wm(wo, wm, d, lambda_o);
        const float co = cos_theta(wo);
        if (uc < pr / (pr + pt)) {
            Vector3f wi = reflect(wo, wm);
            if (!same_hemisphere(wo, wi)) return std::nullopt;
            float pdf = pdf_wm / (4 * std::abs(cos_om)) * pr / (pr + pt);
            if (!(pdf > 0)) return std::nullopt;
            float g = 1 / (1 + lambda_o + distrib_.Lambda(wi));
            return BSDFSample{wi, Bsdf3(SampledSpectrum(reflected(d, g, F, cos_theta(wi), co))),
                              SolidAnglePdf(pdf), kGlossyReflection};
        }
        Vector3f wi;
        float etap;
        if (!refract(wo, wm, fresnel_.eta, &etap, &wi)) return std::nullopt;
        if (same_hemisphere(wo, wi) || wi.z == 0) return std::nullopt;
        const float cos_im = dot(wi, wm);
        float denom = sqr(cos_im + cos_om / etap);
        float pdf = pdf_wm * std::abs(cos_im) / denom * pt / (pr + pt);
        if (!(pdf > 0)) return std::nullopt;
        float g = 1 / (1 + lambda_o + distrib_.Lambda(wi));
        float ft = transmitted(d, g, F, cos_im, cos_om, etap, cos_theta(wi), co, mode);
        BSDFSample s{wi, Bsdf3(SampledSpectrum(ft)), SolidAnglePdf(pdf), kGlossyTransmission};
        s.eta = etap;
        return s;
    }

    SolidAnglePdf pdf_lobes(Vector3f wo, Vector3f wi, TransportMode, Lobes lobes) const {
        float co = cos_theta(wo), ci = cos_theta(wi);
        if (co == 0 || ci == 0) return SolidAnglePdf(0);
        bool reflect = co * ci > 0;
        if ((reflect && lobes == Lobes::Transmission) || (!reflect && lobes == Lobes::Reflection))
            return SolidAnglePdf(0);
        float etap = 1;
        if (!reflect) etap = co > 0 ? fresnel_.eta : 1 / fresnel_.eta;
        Vector3f wm = wi * etap + wo;
        if (length_squared(wm) == 0) return SolidAnglePdf(0);
        wm = normalize(wm);
        if (wm.z < 0) wm = -wm;
        if (dot(wm, wi) * ci < 0 || dot(wm, wo) * co < 0) return SolidAnglePdf(0);
        float pr, pt;
        lobe_weights(fresnel_(dot(wo, wm)), lobes, &pr, &pt);
        if (!(pr + pt > 0)) return SolidAnglePdf(0);
        if (reflect) return SolidAnglePdf(distrib_.pdf_wm(wo, wm) / (4 * abs_dot(wo, wm)) * pr / (pr + pt));
        float denom = sqr(dot(wi, wm) + dot(wo, wm) / etap);
        return SolidAnglePdf(distrib_.pdf_wm(wo, wm) * abs_dot(wi, wm) / denom * pt / (pr + pt));
    }

private:
    // The lobes' weights at a microfacet of Fresnel reflectance R.
    static void lobe_weights(float R, Lobes lobes, float* pr, float* pt) {
        *pr = lobes == Lobes::Transmission ? 0 : R;
        *pt = lobes == Lobes::Reflection ? 0 : 1 - R;
    }
    // The values of the header's f_r and f_t at microfacet wm with D(wm), G2, F = F(wo·wm) at hand; ci, co
    // the cosines of wi and wo, cos_im = wi·wm, cos_om = wo·wm.
    static float reflected(float d, float g, float F, float ci, float co) {
        return d * g * F / std::abs(4 * ci * co);
    }
    static float transmitted(float d, float g, float F, float cos_im, float cos_om, float etap, float ci,
                             float co, TransportMode mode) {
        float denom = sqr(cos_im + cos_om / etap) * ci * co;
        float ft = d * (1 - F) * g * std::abs(cos_im * cos_om / denom);
        return mode == TransportMode::Radiance ? ft / (etap * etap) : ft;
    }

    MicrofacetDistribution distrib_;
    DielectricFresnel fresnel_;
};

} // namespace illum

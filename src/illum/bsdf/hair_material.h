// pbrt-v4's "hair" material: the HairBxDF (hair.h) with its parameters from textures at the hit, and h, the
// offset across the fibre, from the hit's v as pbrt-v4 takes it (h = -1 + 2v; a curve's v runs across its
// width). The fibre's absorption σ_a comes, in this order of precedence, from "sigma_a", from the colour
// "reflectance" (Chiang et al. 2016 eq. 10) or from the melanin concentrations "eumelanin" and
// "pheomelanin" (Chiang §5.1); with none of them, eumelanin 1.3 (pbrt-v4's default brown).
#pragma once

#include "illum/bsdf/hair.h"
#include "illum/bsdf/material.h"
#include "illum/bsdf/pbrt_materials.h"

namespace illum {

class HairMaterial final : public Material {
public:
    // sigma_a (with its spectrum when given as one), else reflectance, else the melanins (either may be
    // null, read as 0).
    struct Absorption {
        SpectralColor sigma_a;
        const ColorTexture* reflectance = nullptr;
        const FloatTexture* eumelanin = nullptr;
        const FloatTexture* pheomelanin = nullptr;
    };
    HairMaterial(Absorption absorption, const FloatTexture* eta, const FloatTexture* beta_m,
                 const FloatTexture* beta_n, const FloatTexture* alpha)
        : absorption_(std::move(absorption)), eta_(eta), beta_m_(beta_m), beta_n_(beta_n), alpha_(alpha) {
        may_be_specular = false;
        SampledWavelengths rgb = SampledWavelengths::rgb_mode();
        albedo_ = estimate_albedo(rgb);
    }

    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        return BSDF(arena.make<HairBxDF>(make(hit, lambda)), hit.shading_frame());
    }
    Color3 albedo(const SurfaceHit&) const override { return albedo_; }

private:
    // NaN-safe clamp (a NaN reads as lo): the render loop must not make the BxDF's constructor throw.
    static float within(float x, float lo, float hi) { return x > lo ? (x < hi ? x : hi) : lo; }

    HairBxDF make(const TextureEvalContext& at, const SampledWavelengths& lambda) const {
        // pbrt-v4 clamps the roughnesses to [0.01, 1].
        float bm = within(beta_m_->evaluate(at), 0.01f, 1), bn = within(beta_n_->evaluate(at), 0.01f, 1);
        float alpha = within(alpha_->evaluate(at), -90, 90), eta = within(eta_->evaluate(at), 1e-3f, 100);
        SampledSpectrum sigma_a;
        if (absorption_.sigma_a.texture) {
            const SpectralColor& sa = absorption_.sigma_a;
            sigma_a = sa.spectrum && lambda.spectral() ? sa.spectrum->sample(lambda)
                                                       : sa.texture->unbounded(at, lambda);
        } else if (absorption_.reflectance) {
            SampledSpectrum c = absorption_.reflectance->albedo(at, lambda);
            for (int i = 0; i < kSpectrumSamples; ++i) c[i] = within(c[i], 0, 1);
            sigma_a = HairBxDF::sigma_a_from_reflectance(c, bn);
        } else {
            float ce = absorption_.eumelanin ? absorption_.eumelanin->evaluate(at) : 0.0f;
            float cp = absorption_.pheomelanin ? absorption_.pheomelanin->evaluate(at) : 0.0f;
            sigma_a = uplift_unbounded(
                HairBxDF::sigma_a_from_concentration(within(ce, 0, 1e4f), within(cp, 0, 1e4f)), lambda);
        }
        for (int i = 0; i < kSpectrumSamples; ++i) sigma_a[i] = within(sigma_a[i], 0, 1e6f);
        float h = within(-1 + 2 * at.uv.y, -1, 1);
        return HairBxDF(h, eta, sigma_a, bm, bn, alpha);
    }

    // The albedo pass's colour: the directional albedo at normal incidence averaged over h, by a fixed
    // quadrature of the sampled weights (textures at their values at the origin).
    Color3 estimate_albedo(const SampledWavelengths& rgb) const {
        TextureEvalContext at;
        Color3 sum;
        const int nh = 8, n = 8; // a midpoint grid over h and the three sample dimensions
        for (int ih = 0; ih < nh; ++ih) {
            at.uv = {0, (ih + 0.5f) / nh};
            HairBxDF b = make(at, rgb);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    for (int k = 0; k < n; ++k)
                        if (auto s = b.sample({0, 0, 1}, (i + 0.5f) / n, {(j + 0.5f) / n, (k + 0.5f) / n},
                                              TransportMode::Radiance))
                            sum += s->weight().rgb();
        }
        return sum / float(nh * n * n * n);
    }

    Absorption absorption_;
    const FloatTexture *eta_, *beta_m_, *beta_n_, *alpha_;
    Color3 albedo_;
};

} // namespace illum

// The materials of pbrt-v4 scene files on top of illum's reflection models. Each evaluates its
// textures at the hit and places one BxDF in the per-thread arena (no heap allocation per ray).
//
// Roughness follows pbrt-v4: with remaproughness (the default) α = sqrt(roughness) (its
// TrowbridgeReitzDistribution::RoughnessToAlpha); a Trowbridge-Reitz (GGX) distribution whose larger α
// is below 1e-3 is treated as smooth (a delta lobe).
#pragma once

#include <cmath>
#include <cstring>

#include "illum/bsdf/coated.h"
#include "illum/bsdf/conductor.h"
#include "illum/bsdf/dielectric.h"
#include "illum/bsdf/diffuse_transmission.h"
#include "illum/bsdf/material.h"
#include "illum/bsdf/rough_conductor.h"
#include "illum/bsdf/rough_dielectric.h"
#include "illum/radiometry/densely_sampled_spectrum.h"

namespace illum {

struct RoughnessParams {
    const FloatTexture* u = nullptr;
    const FloatTexture* v = nullptr;
    bool remap = true;

    // (αx, αy); both 0 for an effectively smooth surface.
    Vector2f alpha(const SurfaceHit& hit) const {
        float ru = std::max(0.0f, u->evaluate(hit)), rv = std::max(0.0f, v->evaluate(hit));
        float ax = remap ? std::sqrt(ru) : ru, ay = remap ? std::sqrt(rv) : rv;
        if (std::max(ax, ay) < 1e-3f) return {0, 0};
        return {std::clamp(ax, 1e-3f, 2.0f), std::clamp(ay, 1e-3f, 2.0f)};
    }
};

inline MicrofacetDistribution ggx(Vector2f a) {
    return MicrofacetDistribution(MicrofacetType::GGX, a.x, a.y);
}

// A scalar parameter that may be a spectrum (an index of refraction): its value for RGB mode and, when
// given as a spectrum, its table, which spectral mode reads at the hero wavelength after terminating the
// others (dispersion, as pbrt-v4's dielectrics do for a non-constant η).
struct DispersiveScalar {
    float value = 1;
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
    float at(SampledWavelengths& lambda) const {
        if (!spectrum || !lambda.spectral()) return value;
        lambda.terminate_secondary();
        return std::clamp((*spectrum)(lambda.hero()), 1e-3f, 100.0f);
    }
};

// An Rgb parameter that may be a spectrum (a named metal's η or k): its texture, and its table when
// given as a constant spectrum.
struct SpectralColor {
    const ColorTexture* texture = nullptr;
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
    SampledSpectrum at(const SurfaceHit& hit, const SampledWavelengths& lambda) const {
        if (spectrum && lambda.spectral()) return spectrum->sample(lambda);
        return texture->unbounded(hit, lambda);
    }
};

// pbrt-v4 "conductor": complex index η + ik, or an artist's normal-incidence `reflectance` r mapped to
// η = 1, k = 2 sqrt(r) / sqrt(1 - r) (so that the Fresnel reflectance at normal incidence is r; in
// spectral mode r is uplifted as a reflectance first, as pbrt-v4 does).
class ConductorMaterial final : public Material {
public:
    ConductorMaterial(SpectralColor eta, SpectralColor k, const ColorTexture* reflectance,
                      RoughnessParams rough)
        : eta_(std::move(eta)), k_(std::move(k)), reflectance_(reflectance), rough_(rough) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        SampledSpectrum eta, k;
        index(hit, lambda, &eta, &k);
        Vector2f a = rough_.alpha(hit);
        const BxDF* b;
        if (a.x == 0)
            b = arena.make<ConductorBxDF>(eta, k);
        else
            b = arena.make<RoughConductorBxDF>(ggx(a), Fresnel{eta, k, FresnelMode::Exact});
        return placed(b, hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        SampledWavelengths rgb = SampledWavelengths::rgb_mode();
        SampledSpectrum eta, k;
        index(hit, rgb, &eta, &k);
        return conductor_f0(eta, k).rgb();
    }
    void index(const SurfaceHit& hit, const SampledWavelengths& lambda, SampledSpectrum* eta,
               SampledSpectrum* k) const {
        if (reflectance_) {
            SampledSpectrum r = clamp(reflectance_->albedo(hit, lambda), 0.0f, 0.9999f);
            *eta = SampledSpectrum(1.0f);
            *k = 2 * sqrt(r) / sqrt(SampledSpectrum(1.0f) - r);
        } else {
            *eta = eta_.at(hit, lambda);
            *k = clamp(k_.at(hit, lambda), 0.0f, 1e4f);
            for (int i = 0; i < kSpectrumSamples; ++i) (*eta)[i] = std::max((*eta)[i], 1e-4f);
        }
    }

private:
    SpectralColor eta_, k_;
    const ColorTexture* reflectance_;
    RoughnessParams rough_;
};

// pbrt-v4 "dielectric": smooth or rough (GGX) interface of relative index η (a spectrally varying η
// disperses in spectral mode and is reduced to one value in RGB mode).
class DielectricMaterial final : public Material {
public:
    DielectricMaterial(DispersiveScalar eta, RoughnessParams rough) : eta_(std::move(eta)), rough_(rough) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        Vector2f a = rough_.alpha(hit);
        float eta = eta_.at(lambda);
        const BxDF* b;
        if (a.x == 0 || eta == 1)
            b = arena.make<DielectricBxDF>(eta);
        else
            b = arena.make<RoughDielectricBxDF>(ggx(a), eta);
        return placed(b, hit);
    }
    Color3 albedo(const SurfaceHit&) const override { return Color3(1.0f); }

private:
    DispersiveScalar eta_;
    RoughnessParams rough_;
};

// The layer of pbrt-v4's coated materials: thickness, medium albedo and asymmetry g (textures), and the
// walk's limits.
struct LayerParams {
    const FloatTexture* thickness = nullptr;
    const ColorTexture* albedo = nullptr;
    const FloatTexture* g = nullptr;
    int max_depth = 10, samples = 1;

    LayerMedium medium(const SurfaceHit& hit, const SampledWavelengths& lambda) const {
        return {std::max(0.0f, thickness->evaluate(hit)), albedo->albedo(hit, lambda),
                std::clamp(g->evaluate(hit), -0.99f, 0.99f)};
    }
};

// pbrt-v4 "coateddiffuse": a dielectric coat (index η, roughness as pbrt-v4 maps it) over a Lambertian
// base, with the layer's medium between; layered.h.
class CoatedDiffuseMaterial final : public Material {
public:
    CoatedDiffuseMaterial(const ColorTexture* reflectance, DispersiveScalar eta, RoughnessParams coat,
                          LayerParams layer)
        : reflectance_(reflectance), eta_(std::move(eta)), coat_(coat), layer_(layer) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        SampledSpectrum r = reflectance_->albedo(hit, lambda);
        return placed(arena.make<CoatedDiffuseBxDF>(DielectricInterface(eta_.at(lambda), coat_.alpha(hit)),
                                                    LambertBxDF(r), layer_.medium(hit, lambda),
                                                    layer_.max_depth, layer_.samples),
                      hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return clamp(reflectance_->evaluate(hit), 0.0f, 1.0f);
    }

private:
    const ColorTexture* reflectance_;
    DispersiveScalar eta_;
    RoughnessParams coat_;
    LayerParams layer_;
};

// pbrt-v4 "coatedconductor": a dielectric coat over a conductor (smooth or rough) whose index is taken
// relative to the coat (η_c / η, k_c / η), as pbrt-v4 does.
class CoatedConductorMaterial final : public Material {
public:
    CoatedConductorMaterial(DispersiveScalar interface_eta, RoughnessParams interface,
                            const ConductorMaterial* conductor, RoughnessParams conductor_rough,
                            LayerParams layer)
        : eta_(std::move(interface_eta)), interface_(interface), conductor_(conductor),
          rough_(conductor_rough), layer_(layer) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        float ieta = eta_.at(lambda);
        SampledSpectrum eta, k;
        conductor_->index(hit, lambda, &eta, &k);
        ConductorInterface base(Fresnel{eta / ieta, k / ieta, FresnelMode::Exact}, rough_.alpha(hit));
        return placed(arena.make<CoatedConductorBxDF>(DielectricInterface(ieta, interface_.alpha(hit)), base,
                                                      layer_.medium(hit, lambda), layer_.max_depth,
                                                      layer_.samples),
                      hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override { return conductor_->albedo(hit); }

private:
    DispersiveScalar eta_;
    RoughnessParams interface_;
    const ConductorMaterial* conductor_;
    RoughnessParams rough_;
    LayerParams layer_;
};

class DiffuseTransmissionMaterial final : public Material {
public:
    DiffuseTransmissionMaterial(const ColorTexture* r, const ColorTexture* t, float scale)
        : r_(r), t_(t), scale_(scale) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        SampledSpectrum r = uplift_albedo(r_->evaluate(hit) * scale_, lambda),
                        t = uplift_albedo(t_->evaluate(hit) * scale_, lambda);
        SampledSpectrum sum = r + t;
        float m = sum.max_component();
        if (m > 1) {
            r /= m;
            t /= m;
        }
        return placed(arena.make<DiffuseTransmissionBxDF>(r, t), hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return clamp(r_->evaluate(hit) * scale_, 0.0f, 1.0f);
    }

private:
    const ColorTexture *r_, *t_;
    float scale_;
};

// pbrt-v4 "interface": no surface at all; the integrators pass straight through an empty BSDF.
class InterfaceMaterial final : public Material {
public:
    BSDF bsdf(const SurfaceHit&, SampledWavelengths&, ScratchArena&) const override { return BSDF(); }
    Color3 albedo(const SurfaceHit&) const override { return Color3(0.0f); }
    bool is_interface() const override { return true; }
    InterfaceMaterial() { may_be_specular = false; }
};

// pbrt-v4 "mix": one of two materials, chosen per hit: the second where amount > u, with u a hash of the
// hit point and the outgoing direction in [0, 1), so the choice is deterministic for a given hit (as in
// pbrt-v4's MixMaterial::ChooseMaterial, which hashes the same quantities).
class MixMaterial final : public Material {
public:
    MixMaterial(const Material* a, const Material* b, const FloatTexture* amount)
        : a_(a), b_(b), amount_(amount) {}
    const Material* choose(const SurfaceHit& hit) const {
        float t = amount_->evaluate(hit);
        if (t <= 0) return a_;
        if (t >= 1) return b_;
        std::uint64_t h = bsdf_detail::hash_floats({hit.p.x, hit.p.y, hit.p.z, hit.wo.x, hit.wo.y, hit.wo.z});
        float u = float(h >> 40) * 0x1p-24f;
        return t < u ? a_ : b_;
    }
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        const Material* m = choose(hit);
        return m ? m->bsdf(hit, lambda, arena) : BSDF();
    }
    const Material* resolve(const SurfaceHit& hit) const override {
        const Material* m = choose(hit);
        return m ? m->resolve(hit) : nullptr;
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        float t = std::clamp(amount_->evaluate(hit), 0.0f, 1.0f);
        return (a_ ? a_->albedo(hit) : Color3(0.0f)) * (1 - t) + (b_ ? b_->albedo(hit) : Color3(0.0f)) * t;
    }

private:
    const Material *a_, *b_;
    const FloatTexture* amount_;
};

} // namespace illum

// pbrt-v4's Option "forcediffuse" (SurfaceInteraction::GetBSDF): every surface scatters as a Lambertian
// reflector whose reflectance is the material's own BSDF's directional albedo ρ(wo) = ∫ f |cos θi| dωi,
// estimated, as pbrt-v4 does, from one sample of the BSDF: ρ ≈ f |cos θi| / p (reflection and
// transmission alike; an unbiased estimate, so the image's expectation is that of a diffuse surface of
// reflectance ρ). pbrt-v4 draws the sample's numbers from the pixel sampler; here they come from a hash of
// the hit point and wo (as the mix material chooses), which only changes the noise. Interfaces stay
// interfaces, and a subsurface material keeps its interior medium.
#pragma once

#include "illum/bsdf/lambert.h"
#include "illum/bsdf/layered.h"
#include "illum/bsdf/material.h"

namespace illum {

class ForceDiffuseMaterial final : public Material {
public:
    explicit ForceDiffuseMaterial(const Material* inner) : inner_(inner) { may_be_specular = false; }

    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        BSDF b = inner_->bsdf(hit, lambda, arena);
        if (!b) return b;
        bsdf_detail::SplitMix64 rng{
            bsdf_detail::hash_floats({hit.p.x, hit.p.y, hit.p.z, hit.wo.x, hit.wo.y, hit.wo.z, 0.5f})};
        float uc = rng.uniform();
        Point2f u = rng.uniform2();
        SampledSpectrum rho(0.0f);
        if (auto s = b.sample(hit.wo, uc, u))
            rho = throughput_weight(s->f, std::abs(dot(s->wi, b.frame().n)), s->pdf);
        return BSDF(arena.make<LambertBxDF>(rho), b.frame());
    }
    Color3 albedo(const SurfaceHit& hit) const override { return inner_->albedo(hit); }
    bool is_interface() const override { return inner_->is_interface(); }
    const Medium* interior() const override { return inner_->interior(); }

private:
    const Material* inner_;
};

} // namespace illum

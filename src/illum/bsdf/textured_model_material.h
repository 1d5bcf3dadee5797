// A reflection model of the registry whose parameters may be textures: at each hit the textures are
// evaluated (clamped to each parameter's range, unit-sum groups scaled to 1, so every point gives a valid
// model) and the model is placed in the scratch arena. No strings, maps, exceptions or heap per hit: the
// parameters were resolved to slots when the scene was built. One class per model (Place is the model's
// stateless constructor), so the constructor and the slot lookups inline into bsdf().
#pragma once

#include "illum/bsdf/material.h"
#include "illum/bsdf/registry.h"

namespace illum {

template <class Place>
class TexturedModelMaterial final : public Material {
public:
    // albedo: what the albedo pass shows where the model has no closed form (its albedo with its textures
    // at their defaults).
    TexturedModelMaterial(ParamValues values, Color3 albedo, ModelFactory::NormalAlbedo normal_albedo)
        : values_(std::move(values)), albedo_(albedo), normal_albedo_(normal_albedo) {}

    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        return placed(Place{}(ModelArgs(values_.args, &hit, &lambda), arena), hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return normal_albedo_ ? normal_albedo_(ModelArgs(values_.args, &hit)) : albedo_;
    }

private:
    ParamValues values_;
    Color3 albedo_;
    ModelFactory::NormalAlbedo normal_albedo_;
};

} // namespace illum

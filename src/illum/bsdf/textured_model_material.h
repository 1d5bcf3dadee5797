// A reflection model of the registry whose parameters may be textures: at each hit the textures are
// evaluated (clamped to each parameter's range, unit-sum groups scaled to 1, so every point gives a valid
// model) and the model is placed in the scratch arena. No strings, maps, exceptions or heap per hit: the
// parameters were resolved to slots when the scene was built.
#pragma once

#include <vector>

#include "illum/bsdf/material.h"
#include "illum/bsdf/registry.h"

namespace illum {

class TexturedModelMaterial final : public Material {
public:
    // albedo: what the albedo pass shows (the model's albedo with its textures at their defaults).
    TexturedModelMaterial(const ModelSpec& spec, ParamValues values, Color3 albedo)
        : place_(spec.factory.place), normal_albedo_(spec.normal_albedo), values_(std::move(values)),
          albedo_(albedo) {}

    BSDF bsdf(const SurfaceHit& hit, ScratchArena& arena) const override {
        return BSDF(place_(ModelArgs(values_.args, &hit), arena), hit.shading_frame());
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return normal_albedo_ ? normal_albedo_(ModelArgs(values_.args, &hit)) : albedo_;
    }

private:
    const std::function<const BxDF*(const ModelArgs&, ScratchArena&)>& place_;
    const std::function<Color3(const ModelArgs&)>& normal_albedo_;
    ParamValues values_;
    Color3 albedo_;
};

} // namespace illum

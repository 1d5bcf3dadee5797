// A reflection model of the registry whose parameters may be textures: at each hit the textures are
// evaluated and the model is placed in the scratch arena (no heap allocation).
#pragma once

#include <vector>

#include "illum/bsdf/material.h"
#include "illum/bsdf/registry.h"

namespace illum {

class TexturedModelMaterial final : public Material {
public:
    // albedo: what the albedo pass shows (the model's albedo with its textures at their defaults).
    TexturedModelMaterial(const ModelSpec& spec, std::vector<ShadingArgs::Value> values, Color3 albedo)
        : spec_(spec), values_(std::move(values)), albedo_(albedo) {}

    BSDF bsdf(const SurfaceHit& hit, ScratchArena& arena) const override {
        ShadingArgs args(values_, hit);
        // Values are clamped to their ranges, so construction succeeds but for constraints between
        // parameters (kd + ks <= 1, say) that a texture breaks: such a point reflects nothing.
        try {
            return BSDF(spec_.factory.place(args, arena), hit.shading_frame());
        } catch (const Error&) {
            return BSDF(arena.make<LambertBxDF>(Color3(0.0f)), hit.shading_frame());
        }
    }
    Color3 albedo(const SurfaceHit&) const override { return albedo_; }

private:
    const ModelSpec& spec_;
    std::vector<ShadingArgs::Value> values_;
    Color3 albedo_;
};

} // namespace illum

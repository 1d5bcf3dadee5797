// The light sampler of next-event estimation, as pbrt-v4's "lightsampler" parameter names it (path,
// volpath; SPPM's visible points use "bvh" as pbrt-v4's do):
//   uniform     every light equally likely;
//   power       in proportion to the light's power (PowerLightSampler);
//   bvh         by the light BVH's importance at the receiver (BvhLightSampler; pbrt-v4's default);
//   exhaustive  in proportion to every bounded light's importance at the receiver (the BVH's estimate
//               without the tree: exact per light, O(lights) per sample); unbounded lights as the BVH has
//               them.
// The bidirectional integrators start light subpaths without a receiver and keep the power sampler, as
// pbrt-v4's bdpt does.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "illum/light/bvh_light_sampler.h"
#include "illum/light/light_sampler.h"

namespace illum {

enum class LightSamplerKind { uniform, power, bvh, exhaustive };
std::optional<LightSamplerKind> parse_light_sampler(std::string_view name);
const char* light_sampler_name(LightSamplerKind kind);

class DirectLightSampler {
public:
    DirectLightSampler() = default;
    DirectLightSampler(const std::vector<const Light*>& lights, LightSamplerKind kind);

    // A light for the receiver ctx and its probability (nullptr: none, or none can reach ctx).
    const Light* sample(const LightSampleContext& ctx, float u, float* pmf) const {
        switch (kind_) {
        case LightSamplerKind::power:
            return power_.sample(u, pmf);
        case LightSamplerKind::bvh:
            return bvh_.sample(ctx, u, pmf);
        default:
            return sample_other(ctx, u, pmf);
        }
    }
    // The probability that sample() picks `light` for ctx.
    float pmf(const LightSampleContext& ctx, const Light* light) const {
        switch (kind_) {
        case LightSamplerKind::power:
            return power_.pmf(light);
        case LightSamplerKind::bvh:
            return bvh_.pmf(ctx, light);
        default:
            return pmf_other(ctx, light);
        }
    }
    LightSamplerKind kind() const { return kind_; }
    const BvhLightSampler& bvh() const { return bvh_; }

private:
    const Light* sample_other(const LightSampleContext& ctx, float u, float* pmf) const;
    float pmf_other(const LightSampleContext& ctx, const Light* light) const;

    LightSamplerKind kind_ = LightSamplerKind::power;
    std::vector<const Light*> lights_;
    PowerLightSampler power_;
    BvhLightSampler bvh_;
    // exhaustive: the split, and the bounded lights with their bounds.
    LightSplit split_;
    std::vector<const Light*> bounded_;
    std::vector<PreparedLightBounds> bounds_;
};

} // namespace illum

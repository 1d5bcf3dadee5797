#include "illum/light/direct_light_sampler.h"

#include <algorithm>
#include <cmath>

namespace illum {

std::optional<LightSamplerKind> parse_light_sampler(std::string_view name) {
    if (name == "uniform") return LightSamplerKind::uniform;
    if (name == "power") return LightSamplerKind::power;
    if (name == "bvh") return LightSamplerKind::bvh;
    if (name == "exhaustive") return LightSamplerKind::exhaustive;
    return std::nullopt;
}

const char* light_sampler_name(LightSamplerKind kind) {
    switch (kind) {
    case LightSamplerKind::uniform:
        return "uniform";
    case LightSamplerKind::power:
        return "power";
    case LightSamplerKind::bvh:
        return "bvh";
    case LightSamplerKind::exhaustive:
        return "exhaustive";
    }
    return "power";
}

DirectLightSampler::DirectLightSampler(const std::vector<const Light*>& lights, LightSamplerKind kind)
    : kind_(kind), lights_(lights) {
    switch (kind) {
    case LightSamplerKind::power:
        power_ = PowerLightSampler(lights);
        break;
    case LightSamplerKind::bvh:
        bvh_ = BvhLightSampler(lights);
        break;
    case LightSamplerKind::uniform:
        break;
    case LightSamplerKind::exhaustive:
        split_ = LightSplit(lights);
        for (const BoundedLight& b : split_.bounded()) {
            bounded_.push_back(b.light);
            bounds_.push_back(PreparedLightBounds(b.bounds));
        }
        break;
    }
}

const Light* DirectLightSampler::sample_other(const LightSampleContext& ctx, float u, float* pmf) const {
    *pmf = 0;
    if (kind_ == LightSamplerKind::uniform) {
        if (lights_.empty()) return nullptr;
        std::size_t i = std::min(std::size_t(u * float(lights_.size())), lights_.size() - 1);
        *pmf = 1.0f / float(lights_.size());
        return lights_[i];
    }
    // exhaustive: the unbounded lights as the BVH has them, then the bounded ones by importance.
    if (const Light* l = split_.pick_unbounded(&u, pmf)) return l;
    float total = 0;
    for (const PreparedLightBounds& b : bounds_) total += b.importance(ctx.p, ctx.n);
    if (!(total > 0)) return nullptr;
    float target = u * total, running = 0, chosen_importance = 0;
    std::size_t chosen = bounded_.size();
    for (std::size_t i = 0; i < bounds_.size(); ++i) {
        float c = bounds_[i].importance(ctx.p, ctx.n);
        if (c <= 0) continue;
        chosen = i, chosen_importance = c; // the last light of nonzero importance catches rounding at the top
        running += c;
        if (target < running) break;
    }
    *pmf = split_.bounded_share() * chosen_importance / total;
    return bounded_[chosen];
}

float DirectLightSampler::pmf_other(const LightSampleContext& ctx, const Light* light) const {
    if (!light) return 0;
    if (kind_ == LightSamplerKind::uniform) return lights_.empty() ? 0.0f : 1.0f / float(lights_.size());
    if (std::optional<float> p = split_.unbounded_pmf(light)) return *p;
    float total = 0, mine = 0;
    for (std::size_t i = 0; i < bounds_.size(); ++i) {
        float c = bounds_[i].importance(ctx.p, ctx.n);
        total += c;
        if (bounded_[i] == light) mine = c;
    }
    return total > 0 ? split_.bounded_share() * mine / total : 0.0f;
}

} // namespace illum

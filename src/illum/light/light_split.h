// The lights as pbrt-v4's BVH and exhaustive samplers divide them (PBR 4th ed. §12.6.3): the bounded ones
// of nonzero strength, which those samplers pick by their importance at the receiver, and the unbounded
// ones (at infinity), picked apart and uniformly, each as often as all the bounded ones together: the
// bounded lights' share is 1 / (unbounded + 1). Lights of zero strength are in neither and never picked.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "illum/light/light.h"

namespace illum {

struct BoundedLight {
    const Light* light;
    LightBounds bounds;
};

class LightSplit {
public:
    LightSplit() = default;
    explicit LightSplit(const std::vector<const Light*>& lights);

    // The bounded lights with their bounds, in the lights' order (a sampler may reorder them).
    std::vector<BoundedLight>& bounded() { return bounded_; }
    // One more than the largest Light::index among the lights (for tables by index).
    std::uint32_t index_count() const { return std::uint32_t(is_unbounded_.size()); }
    bool empty() const { return !any_bounded_ && unbounded_.empty(); }

    // The share of the bounded lights: 1 / (unbounded + 1), zero when there are none.
    float bounded_share() const { return any_bounded_ ? 1.0f / float(unbounded_.size() + 1) : 0.0f; }
    // From u in [0, 1): one of the unbounded lights and its probability; or nullptr, *pmf 0, with *u
    // rescaled to [0, 1) over the bounded lights' share.
    const Light* pick_unbounded(float* u, float* pmf) const;
    // The probability with which pick_unbounded() returns `light`; nullopt when it is not unbounded.
    std::optional<float> unbounded_pmf(const Light* light) const {
        if (!light || light->index >= is_unbounded_.size() || !is_unbounded_[light->index])
            return std::nullopt;
        return (1 - bounded_share()) / float(unbounded_.size());
    }

private:
    std::vector<BoundedLight> bounded_;
    bool any_bounded_ = false;
    std::vector<const Light*> unbounded_;
    std::vector<std::uint8_t> is_unbounded_; // by Light::index
};

} // namespace illum

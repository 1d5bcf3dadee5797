// Picks a light for next-event estimation with probability proportional to its power (luminance of
// Φ). Lights of zero power (a black emitter) are never picked; environment lights, whose power
// depends on the scene size, take part like any other.
#pragma once

#include <vector>

#include "illum/light/light.h"
#include "illum/math/distribution.h"

namespace illum {

class PowerLightSampler {
public:
    PowerLightSampler() = default;
    explicit PowerLightSampler(const std::vector<const Light*>& lights);

    // The light and its probability; nullptr when the scene has no light.
    const Light* sample(float u, float* pmf) const {
        if (lights_.empty()) return nullptr;
        return lights_[std::size_t(table_.sample(u, pmf))];
    }
    float pmf(const Light* light) const;
    bool empty() const { return lights_.empty(); }

private:
    std::vector<const Light*> lights_;
    std::vector<float> pmf_; // indexed by Light::index
    AliasTable table_;
};

} // namespace illum

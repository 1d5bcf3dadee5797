#include "illum/light/light_sampler.h"

namespace illum {

PowerLightSampler::PowerLightSampler(const std::vector<const Light*>& lights) : lights_(lights) {
    if (lights_.empty()) return;
    std::vector<float> weights;
    for (const Light* l : lights_) {
        float phi = l->power().rgb().luminance();
        weights.push_back(std::isfinite(phi) && phi > 0 ? phi : 0.0f);
    }
    bool any = false;
    for (float w : weights) any |= w > 0;
    if (!any) std::fill(weights.begin(), weights.end(), 1.0f);
    table_ = AliasTable(weights);
    pmf_.resize(lights_.size());
    for (std::size_t i = 0; i < lights_.size(); ++i) pmf_[i] = table_.pmf(int(i));
}

float PowerLightSampler::pmf(const Light* light) const {
    if (!light || light->index >= pmf_.size()) return 0;
    return pmf_[light->index];
}

} // namespace illum

#include "illum/light/light_split.h"

#include <algorithm>
#include <cmath>

namespace illum {

LightSplit::LightSplit(const std::vector<const Light*>& lights) {
    std::uint32_t count = 0;
    for (const Light* l : lights) count = std::max(count, l->index + 1);
    is_unbounded_.assign(count, 0);
    for (const Light* l : lights) {
        std::optional<LightBounds> b = l->bounds();
        if (!b) {
            unbounded_.push_back(l);
            is_unbounded_[l->index] = 1;
        } else if (std::isfinite(b->phi) && b->phi > 0) {
            bounded_.push_back({l, *b});
        }
    }
    any_bounded_ = !bounded_.empty();
}

const Light* LightSplit::pick_unbounded(float* u, float* pmf) const {
    *pmf = 0;
    if (unbounded_.empty()) return nullptr; // the bounded lights' share is all of [0, 1)
    const float p_bounded = bounded_share(), p_unbounded = 1 - p_bounded;
    if (*u < p_unbounded) {
        std::size_t i =
            std::min(std::size_t(*u / p_unbounded * float(unbounded_.size())), unbounded_.size() - 1);
        *pmf = p_unbounded / float(unbounded_.size());
        return unbounded_[i];
    }
    *u = std::min((*u - p_unbounded) / p_bounded, 0x1.fffffep-1f);
    return nullptr;
}

} // namespace illum

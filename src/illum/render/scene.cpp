#include "illum/render/scene.h"

#include "illum/bsdf/material.h"

namespace illum {

void Scene::finalize() {
    accelerator.commit();
    // Shadow rays in media pass surfaces without material and interface boundaries (shadow_transmittance).
    accelerator.mark_passable([](const Material* m) { return !m || m->is_interface(); });
    std::vector<const Light*> all;
    infinite_lights.clear();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        lights[i]->index = std::uint32_t(i);
        lights[i]->preprocess(accelerator.bounds());
        all.push_back(lights[i].get());
        if (lights[i]->type() == LightType::Infinite) infinite_lights.push_back(lights[i].get());
    }
    light_sampler = PowerLightSampler(all);
    set_light_sampler(request.light_sampler);
}

void Scene::set_light_sampler(LightSamplerKind kind) {
    request.light_sampler = kind;
    std::vector<const Light*> all;
    for (const auto& l : lights) all.push_back(l.get());
    direct_light_sampler = DirectLightSampler(all, kind);
}

} // namespace illum

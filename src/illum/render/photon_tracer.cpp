#include "illum/render/photon_tracer.h"

#include "illum/light/light.h"

namespace illum {

bool PhotonTracer::emit(std::uint64_t global_index, const SampledWavelengths& lambda, Sampler& sampler,
                        EmittedPhoton* out) const {
    start_photon_sample(sampler, global_index);
    float u_light = sampler.get_1d();
    Point2f u_pos = sampler.get_2d(), u_dir = sampler.get_2d();
    float pmf = 0;
    const Light* light = scene_.light_sampler.sample(u_light, &pmf);
    if (!light || !(pmf > 0)) return false;
    // Motion blur: the photon's time, drawn in the shutter interval as a camera sample's is (a moving
    // light emits it from where it is then).
    const float time = scene_.has_motion ? scene_.sample_time(sampler.get_1d()) : 0.0f;
    auto le = light->sample_le_at(time, u_pos, u_dir, lambda);
    if (!le || le->flux.is_black()) return false;
    // β = Φ_sample / p_light, Φ_sample = L |cos θ| / (p_pos p_dir) (LightLeSample::flux).
    out->ray = le->ray;
    out->beta = le->flux.s / pmf;
    return out->beta.is_finite();
}

} // namespace illum

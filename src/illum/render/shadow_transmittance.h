// The transmittance of a shadow ray or a connection through participating media (PBR 4th ed. §14.2.2):
// the ray passes surfaces without material (pbrt-v4's "interface") into the media they separate and is
// blocked by any other surface. A homogeneous medium's transmittance exp(-σ_t d) is evaluated exactly; in
// any other medium it is estimated by ratio tracking against the majorant, with roulette once small.
//
// r_u and r_l (per channel, relative to the sampling channel) are multiplied by the densities with which
// the unidirectional and the light-sampling technique produce the segments crossed, for spectral MIS
// (volpath_integrator.h): ratio tracking's as in the null-scattering formulation; the exact evaluation has
// density 1 for light sampling and T for the unidirectional technique.
#pragma once

#include <cstdint>

#include "illum/math/rng.h"
#include "illum/medium/medium.h"
#include "illum/radiometry/sampled_wavelengths.h"
#include "illum/render/scene.h"

namespace illum {

// Where the shadow ray ends: a point with its error bound and normal (zero normal: a point with no
// surface, such as a lens or a point light), or a direction to infinity.
struct ShadowTarget {
    Point3f p;
    Vector3f p_error;
    Normal3f n;
    bool at_infinity = false;
    Vector3f wi; // at_infinity: the direction
};

// A ray in vacuum in a scene with nothing passable (every scene without media): it is blocked or clear,
// one plain occlusion test answers it.
inline bool is_plain_occlusion(const Scene& scene, const Ray& ray) {
    return !ray.medium && !scene.accelerator.any_passable();
}

// `ray` starts at the shading point, in its medium, aimed at the target (ray.tmax just short of it, or
// infinite). Counts the rays it traces in *rays.
SampledSpectrum shadow_transmittance(const Scene& scene, Ray ray, const ShadowTarget& target, int channel,
                                     PCG32& rng, const SampledWavelengths& lambda, SampledSpectrum* r_u,
                                     SampledSpectrum* r_l, std::uint64_t* rays,
                                     HomogeneousCache* cache = nullptr);

// The majorant transmittance over the sampling channel's (the density with which a walk passed a segment
// without a collision in that channel); zero where the channel's is zero.
inline SampledSpectrum relative_to_channel(SampledSpectrum t_maj, int channel) {
    return t_maj[channel] > 0 ? t_maj / t_maj[channel] : SampledSpectrum(0.0f);
}

} // namespace illum

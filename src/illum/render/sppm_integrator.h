// Stochastic progressive photon mapping (T. Hachisuka, H. W. Jensen, "Stochastic Progressive Photon
// Mapping", SIGGRAPH Asia 2009; PBR 3rd ed. §16.2 and pbrt-v4's SPPMIntegrator, whose parameters and
// behaviour this follows). Each iteration:
//
//  1. Camera pass: one camera path per pixel up to its first diffuse vertex (or a glossy one at the last
//     depth), the visible point x with its throughput β_cam and outgoing direction ω_o. Emission seen along
//     the way (directly or through specular chains) and next-event estimation at every vertex up to x
//     (with one more BSDF-sampled bounce for its MIS partner) go to the pixel's direct radiance L_d.
//  2. A hash grid of the visible points, sized by their current radii R (visible_point_grid.h).
//  3. Photon pass: N photons from the lights (photon_tracer.h); at every surface they reach after their
//     first bounce (the first hit is direct light, already in L_d), each visible point within R of the hit
//     gathers Φ_i += β_cam · f(x, ω_o, ω_photon) · β_photon and M_i += 1.
//  4. Progressive update (Hachisuka & Jensen eqs. 7-8 with α = γ = 2/3):
//       N_new = N + γ M,   R_new = R √(N_new / (N + M)),   τ_new = (τ + Φ_i) R_new² / R²,
//     then Φ_i = M = 0.
//
// The image after k iterations: L = L_d / k + τ / (k N π R²) (N photons per iteration; τ / (π R²) is the
// density estimate of the reflected flux, of which k N photons were shot). The estimate is consistent:
// its bias (the blur of radius R) vanishes as R → 0 while the variance of the density estimate stays
// bounded because N grows faster than R² shrinks.
//
// Spectral mode (pbrt-v4): one set of wavelengths per iteration, shared by the camera paths and the
// photons, from the base-3 radical inverse of the iteration; Φ_i and L_d are film RGB (the sensor's
// response to the spectral sample) so that iterations with different wavelengths add up.
//
// Determinism: photon gathers are accumulated per fixed chunk of photons (chunks depend on the image size
// and photon count only), each chunk traced in photon order by one task into its own Φ and M arrays, and
// the chunks are summed in chunk order. So the floating-point sums, and the image, do not depend on the
// thread count or scheduling.
#pragma once

#include <cstdint>

#include "illum/render/renderer.h"

namespace illum {

struct SppmSettings {
    int max_depth = 5;                    // pbrt-v4 "maxdepth": camera path depth and photon surface hits
    long long photons_per_iteration = -1; // "photonsperiteration"; -1: the number of pixels
    float initial_radius = 1;             // "radius": the initial search radius [world units]
    std::uint64_t seed = 6502;            // "seed": the photon streams' (combined with --seed)
};

// What a render did besides the image.
struct SppmStats {
    int iterations = 0;
    std::uint64_t photons = 0;        // emitted in all
    std::uint64_t photon_gathers = 0; // (photon, visible point) pairs within the radius
    std::size_t grid_bytes = 0;       // the visible-point grid's largest size over the iterations
    std::size_t grid_entries = 0;     // its entries then
    std::size_t pixel_bytes = 0;      // per-pixel state (visible points, τ, N, R, L_d)
    std::size_t chunk_bytes = 0;      // the per-chunk Φ and M arrays
    std::size_t bsdf_bytes = 0;       // the visible points' BSDFs (arena capacity)
    double photon_seconds = 0;        // in the photon passes
    float final_radius_min = 0, final_radius_max = 0;
};

class SPPMIntegrator final : public WholeImageIntegrator {
public:
    SPPMIntegrator(const Scene& scene, const SppmSettings& settings)
        : WholeImageIntegrator(scene), settings_(settings) {}
    // options.spp is the number of iterations (pbrt-v4: the sampler's pixel samples); time budgets render
    // whole iterations until the budget is spent.
    RenderResult render_image(const RenderOptions& options) const override;
    RenderResult render_sppm(const RenderOptions& options, SppmStats* stats) const;
    const SppmSettings& settings() const { return settings_; }
    long long photons_per_iteration() const;

private:
    SppmSettings settings_;
};

} // namespace illum

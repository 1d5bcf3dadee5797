// The lobe of a reflection model as the plots draw it, and its integral.
//
// For light arriving from wi (towards the light, the shading normal on +z), the lobe is the share of the
// arriving power scattered per steradian towards ω:
//   I(ω) = f(ω, wi) |cos θ_ω|   [1/sr]   (f in radiance mode: light travels from wi to ω),
// evaluated as the adjoint f_importance(wi, ω) |cos θ_ω| (PBR 4th ed. §13.1: importance mode is the
// transpose of radiance mode), which is the integrand of `illum brdf albedo` with θo = θi, so that
//   ∫ I(ω) dω = ρ(wi) = ∫ f_importance(wi, ω) |cos θ_ω| dω,
// the directional albedo that `illum brdf albedo --theta θi` prints. The plotted albedo curve ρ(θi) is this
// integral of the plotted lobe grid, no separate computation.
//
// The grid covers the sphere (the reflecting hemisphere, and the other one when the model transmits) in
// midpoint cells of n_theta x 2 n_theta per hemisphere; its integral is Σ I sin θ Δθ Δφ. Delta lobes
// (a mirror, smooth glass, a smooth coat), which f() does not describe, are spikes: the directions of the
// model's specular samples with the share of the power each carries, estimated from stratified
// samples of sample() (exact for the one- and two-lobe smooth models up to the stratification).
#pragma once

#include <array>
#include <vector>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/bxdf.h"

namespace illum {

struct LobeOptions {
    int n_theta = 180;        // midpoint cells in θ per hemisphere (φ has twice as many)
    int spike_samples = 4096; // stratified samples of sample() for the delta spikes
    std::uint64_t seed = 1;
};

struct LobeSpike {
    Vector3f direction;
    Rgb64 share{}; // fraction of the arriving power in this delta lobe
};

struct LobeGrid {
    Vector3f wi;
    int n_theta = 0, n_phi = 0;
    bool both_hemispheres = false; // rows n_theta .. 2 n_theta - 1 hold the lower hemisphere
    std::vector<Rgb64> values;     // I(ω) per cell, row-major in θ (from the +z pole) then φ
    std::vector<LobeSpike> spikes;

    int rows() const { return both_hemispheres ? 2 * n_theta : n_theta; }
    const Rgb64& at(int row, int col) const {
        return values[std::size_t(row) * std::size_t(n_phi) + std::size_t(col)];
    }
    // The centre of a cell: θ in [0, π] from +z, φ in [0, 2π).
    double theta(int row) const;
    double phi(int col) const;
    Vector3f direction(int row, int col) const;
    // Σ I sin θ Δθ Δφ over the cells: the part of the albedo f() describes.
    Rgb64 integral_of_f() const;
    // integral_of_f() plus the spikes' shares: the directional albedo ρ(wi).
    Rgb64 albedo() const;
};

LobeGrid sample_lobe(const BxDF& bxdf, Vector3f wi, const LobeOptions& options = {});

// I(ω) at one direction (RGB). (A layered model's f() is a random-walk estimate seeded by the directions:
// its lobe is noisy, and its "samples" parameter averages more walks.)
Rgb64 lobe_value(const BxDF& bxdf, Vector3f wi, Vector3f w);

// The lobe in the plane of incidence (the plane through the normal and wi): I at ψ from the normal,
// ψ in [-180°, 180°), positive on wi's side (ω = sin ψ (cos φi, sin φi, 0) + cos ψ (0, 0, 1)), so the
// mirror direction is at ψ = -θi and transmission at |ψ| > 90°.
struct PlaneSample {
    double psi_deg = 0;
    Rgb64 value{};
};
std::vector<PlaneSample> lobe_in_plane(const BxDF& bxdf, Vector3f wi, int samples = 720);

// ρ(θi) at azimuth φi for each θi, each the albedo() of the lobe grid at that wi.
struct AlbedoPoint {
    double theta_deg = 0;
    Rgb64 albedo{}, of_f{};
};
std::vector<AlbedoPoint> albedo_curve(const BxDF& bxdf, double phi_deg, const std::vector<double>& thetas_deg,
                                      const LobeOptions& options = {});

inline double channel_mean(const Rgb64& c) { return (c[0] + c[1] + c[2]) / 3; }

} // namespace illum

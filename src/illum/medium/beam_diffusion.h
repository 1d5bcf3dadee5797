// Photon beam diffusion (PBD): the radial profile of light leaving a homogeneous half-space after a beam
// entered it at normal incidence, and its integral, the effective albedo ρ_eff, which the "subsurface"
// material inverts to turn a reflectance and a mean free path into scattering coefficients.
//
// Habel, Christensen & Jarosz 2013, "Photon Beam Diffusion: A Hybrid Monte Carlo Method for Subsurface
// Scattering" (EGSR), in the form of Pharr, Jakob & Humphreys, "Physically Based Rendering", 3rd/4th ed.,
// §15.5 (pbrt-v4's BeamDiffusionSS / BeamDiffusionMS / ComputeBeamDiffusionBSSRDF). The beam travels down
// the depth axis; with σ's = (1 - g) σ_s, σ't = σ_a + σ's, ρ' = σ's / σ't:
//
//   single scattering, exact (t: depth of the scattering event, d = √(r² + t²), cos θ_o = t / d):
//     S_ss(r) = ∫_{t_c}^∞ σ_s e^{-σ_t t} e^{-σ_t d} / d² · p_HG(-cos θ_o) · (1 - F_r(cos θ_o)) · cos θ_o dt
//     with F_r the Fresnel reflectance from inside (index η) to outside (index 1) and t_c = r √(η² - 1), the
//     depth below which the exit direction is totally internally reflected;
//   multiple scattering, a dipole per depth of the beam's first scattering (real source at z, virtual at
//   z_v = 2 z_e - z) with Grosjean's diffusion coefficient D = (2σ_a + σ's) / (3 σ't²), σ_tr = √(σ_a / D),
//   the extrapolated boundary z_e = -2 D (1 + 3 F̄₂) / (1 - 2 F̄₁) and d'Eon's exitance
//   c_φ φ + c_E E·n, c_φ = (1 - 2 F̄₁) / 4, c_E = (1 - 3 F̄₂) / 2:
//     φ(r, z)   = (e^{-σ_tr d_r} / d_r - e^{-σ_tr d_v} / d_v) / (4π D)
//     E·n(r, z) = (z (1 + σ_tr d_r) e^{-σ_tr d_r} / d_r³ - z_v (1 + σ_tr d_v) e^{-σ_tr d_v} / d_v³) / (4π)
//     S_ms(r)   = ∫_0^∞ σ't e^{-σ't z} ρ'² κ(r, z) (c_φ φ + c_E E·n) dz,  κ = 1 - e^{-2 σ't (d_r + z)}
//   (κ is PBD's correction that keeps the dipole from counting light that leaves right at the entry).
//
// ρ_eff = ∫_0^∞ 2π r (S_ss + S_ms) dr depends only on the single-scattering albedo α = σ_s / σ_t, g and η
// (distances scale with 1 / σ_t). It is not exactly energy conserving: for g = 0, η = 1.33, ρ_eff(1) = 1.033
// (pbrt-v4's table, truncated at r = 203 / σ_t, has 1.019).
//
// Departures from pbrt-v4, with reasons: pbrt-v4 evaluates both depth integrals with 100 midpoint samples
// of the exponential, tabulates r·S at 64 radii (r ≤ 203 / σ_t) and integrates a Catmull-Rom spline; here
// the depth and radius integrals use composite Gauss-Legendre rules on log-spaced panels (converged to
// ~1e-6, checked by refinement in the tests), because the midpoint rule misses the 1/d² peak of S_ss at small
// r. ρ_eff is tabulated over s = √(1 - α) (it is analytic in s near α = 1, where σ_tr ∝ s) and interpolated
// with a monotone cubic, so inversion is well defined; pbrt-v4 uses 100 albedos spaced as
// (1 - e^{-8i/99}) / (1 - e^{-8}) and a Catmull-Rom spline. Measured against pbrt-v4's own table (tests),
// the inverted albedos agree within the differences of the two quadratures.
#pragma once

#include <vector>

namespace illum {

// The Fresnel moments F̄ᵢ(η) = ∫₀¹ F_r(μ) μⁱ dμ of the reflectance seen from inside a medium of relative
// index η, by the polynomial fits of d'Eon & Irving 2011, "A Quantized-Diffusion Model for Rendering
// Translucent Materials" (SIGGRAPH), §5 (the fits pbrt-v4 uses).
double fresnel_moment1(double eta);
double fresnel_moment2(double eta);

// Unpolarised Fresnel reflectance for light inside a medium of relative index eta (inside / outside)
// reaching its boundary with cosine cos_inside to the normal; 1 beyond the critical angle.
double fresnel_dielectric_from_inside(double cos_inside, double eta);

// The PBD profile terms [per unit area] at radius r (same length unit as 1 / σ), for coefficients σ_s,
// σ_a (σ_s + σ_a > 0), Henyey-Greenstein g in (-1, 1), relative index eta > 0.
double beam_diffusion_ss(double sigma_s, double sigma_a, double g, double eta, double r);
double beam_diffusion_ms(double sigma_s, double sigma_a, double g, double eta, double r);

// ρ_eff for single-scattering albedo α in [0, 1], integrated directly. `refine` multiplies the number of
// quadrature panels (the tests use 2 to estimate the quadrature error).
double pbd_effective_albedo(double albedo, double g, double eta, int refine = 1);

// ρ_eff(α) tabulated for one (eta, g), as the subsurface material needs it; built once per material
// (about 30 ms).
class EffectiveAlbedoTable {
public:
    static constexpr int kDefaultNodes = 64;
    EffectiveAlbedoTable(float eta, float g, int nodes = kDefaultNodes);

    float eta() const { return eta_; }
    float g() const { return g_; }
    // ρ_eff at albedo α (clamped to [0, 1]); monotone non-decreasing in α.
    float effective_albedo(float albedo) const;
    // The albedo α whose ρ_eff is rho_eff: 0 below ρ_eff(0) = 0, 1 above ρ_eff(1) (as pbrt-v4 clamps).
    float albedo(float rho_eff) const;
    // The tabulated ρ_eff at the nodes α_i = 1 - s_i², s_i = 1 - i / (n - 1) (α increasing with i).
    const std::vector<double>& node_albedos() const { return albedo_; }
    const std::vector<double>& node_values() const { return rho_; }

private:
    double hermite(int i, double t) const;
    float eta_, g_;
    std::vector<double> s_, albedo_, rho_, slope_; // slope_: dρ/ds at the nodes (Fritsch-Carlson)
};

// pbrt-v4's InvertCatmullRom(rhoSamples, rhoEff, ρ_eff) in SubsurfaceFromDiffuse, with this table.
inline float albedo_from_effective_reflectance(float rho_eff, const EffectiveAlbedoTable& table) {
    return table.albedo(rho_eff);
}

} // namespace illum

// pbrt-v4's "measured" material: a BRDF measured by the RGL gonio-photometer and stored in a `.bsdf`
// tensor file (Dupuy & Jakob 2018, "An Adaptive Parameterization for Efficient Material Acquisition and
// Rendering"). The tables, on the unit square u = (u_θ, u_φ), θ = u_θ² π/2, φ = (2 u_φ - 1) π:
//   ndf      D(m), the microfacet normal distribution, at u(m);
//   sigma    σ(wo) = ∫ D(m) <wo, m>₊ dm, the microsurface's projected area, at u(wo);
//   vndf     the visible normals' density at u(m), a warp conditioned on (φo, θo) (the nodes `phi_i`,
//            `theta_i`); isotropic files (at most 2 φo nodes) store m's azimuth relative to φo;
//   luminance a density on the vndf warp's input square, conditioned likewise: sampling it first makes the
//            sampled directions follow f cos θi (the "adaptive parameterisation");
//   spectra  (or `rgb` in RGB files) R on that input square, conditioned on (φo, θo, λ) (`wavelengths`,
//            nm), with
//     f(wo, wi) = R(s, φo, θo, λ) D(m) / (4 σ(wo) cos θi),   m = normalize(wo + wi),  s = vndf⁻¹(u(m)).
// Sampling: s from the luminance warp, u(m) = vndf(s), wi = reflect(wo, m), with the density
//   p(wi) = p_lum(s) p_vndf(u(m)) / (4 (wo·m) 2π² u_θ sin θm)
// (2π² u_θ sin θm is the Jacobian of the map from the unit square to directions). As pbrt-v4, the
// `jacobian` flag of the file is read but not used (the factor D / (4 σ cos θi) is always applied),
// anisotropic files must cover the full circle of φo (no symmetry reduction), and the model reflects on
// both sides (wo below the surface mirrors both directions).
//
// Spectral mode evaluates the spectra at the path's wavelengths; RGB mode uses the tables reduced to
// linear sRGB once when the file is read (each node's spectrum, piecewise linear, weighted by D65: a grey
// spectrum gives a grey RGB). An RGB file (field `rgb`, no wavelengths, as Mitsuba's RGB variants read)
// is used as is in RGB mode and uplifted as a reflectance in spectral mode; pbrt-v4 reads only spectral
// files.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/tensor_file.h"
#include "illum/math/piecewise_bilinear_2d.h"
#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

struct RglBrdf {
    std::string description;
    bool isotropic = true;
    PiecewiseBilinear2D ndf, sigma, vndf, luminance;
    std::vector<float> wavelengths; // nm; empty for an RGB file
    PiecewiseBilinear2D spectra;    // conditioned on (φo, θo, λ); spectral files only
    PiecewiseBilinear2D rgb;        // conditioned on (φo, θo, channel 0..2)

    bool spectral() const { return !wavelengths.empty(); }
    // Checks the fields' presence, types and shapes as pbrt-v4 does; throws illum::Error naming `name`.
    static RglBrdf from_tensor(const TensorFile& file, const std::string& name);
    static std::shared_ptr<const RglBrdf> read(const std::string& path) {
        return std::make_shared<const RglBrdf>(from_tensor(TensorFile::read(path), path));
    }
};

// The unit-square coordinates of the file's parameterisation.
inline float rgl_theta_to_u(float theta) { return std::sqrt(theta * (2 / kPi)); }
inline float rgl_phi_to_u(float phi) { return phi * (1 / (2 * kPi)) + 0.5f; }
inline float rgl_u_to_theta(float u) { return u * u * (kPi / 2); }
inline float rgl_u_to_phi(float u) { return (2 * u - 1) * kPi; }

class MeasuredBxDF final : public BxDF {
public:
    // `lambda`: the path's wavelengths (spectral mode), or null / an RGB-mode one for RGB. `owner` keeps the
    // data alive for a BxDF on the heap (tools, audits); the arena's BxDFs borrow the material's.
    MeasuredBxDF(const RglBrdf* data, const SampledWavelengths* lambda,
                 std::shared_ptr<const RglBrdf> owner = nullptr);

    std::uint8_t flags() const override { return kGlossyReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override;
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override;
    bool reads_lobe_sample() const override { return false; }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override;

private:
    // R at the vndf input point s, for wo at (φo, θo).
    SampledSpectrum reflectance(Point2f s, float phi_o, float theta_o) const;
    // u(m): m's azimuth relative to φo for isotropic data, wrapped into [0, 1).
    Point2f u_of_normal(Vector3f m, float phi_o) const;

    const RglBrdf* data_;
    SampledWavelengths lambda_;
    bool spectral_ = false;
    std::shared_ptr<const RglBrdf> owner_;
};

} // namespace illum

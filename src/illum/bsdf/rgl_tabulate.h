// Tabulating an analytic microfacet BRDF in the RGL `.bsdf` layout (bsdf/measured.h), for tests, the
// audit's `synthetic:` case and comparison scenes: no measured file can be shipped, so a file made from a
// BRDF known in closed form lets the measured model be checked against that BRDF. Isotropic: one φo node.
//   ndf, sigma  D(m) and σ(wo) = cos θo (1 + Λ(wo)) (Smith; Heitz 2014, eq. 2) on an n x n grid of u;
//   vndf        D(m) <wo, m>₊ 2π² u_θ sin θm at each θo node (the warp normalises it: the visible
//               normals' density on the unit square);
//   spectra     R(s) = f(wo, wi, λ) 4 σ(wo) cos θi / D(m) at the nodes s of the vndf warp's input square,
//               m = vndf(s), wi = reflect(wo, m), with D and σ the tables' own interpolants, so that the
//               measured model reproduces f exactly at the nodes;
//   luminance   the mean of R over the wavelengths at each node.
#pragma once

#include <functional>
#include <vector>

#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"
#include "illum/bsdf/tensor_file.h"

namespace illum {

struct RglTabulation {
    int theta_nodes = 16;                        // θo nodes, uniform in u_θ over [0, 1] (θo in [0, π/2])
    int grid = 32;                               // nodes of each unit-square table along x and y
    std::vector<float> wavelengths = {360, 830}; // nm
    std::string description = "tabulated by illum (rgl_tabulate)";
};

// f(wo, wi, λ): the BRDF [1/sr] for wo, wi on +z at wavelength λ [nm].
using SpectralBrdf = std::function<float(Vector3f wo, Vector3f wi, float lambda)>;
TensorFile tabulate_rgl(const MicrofacetDistribution& d, const SpectralBrdf& f, const RglTabulation& t);

// A GGX rough conductor (height-correlated Smith G2, the exact Fresnel of a conductor with η = 1 and
// k = 2 sqrt(r) / sqrt(1 - r), pbrt-v4's "reflectance" form), r(λ) = `reflectance(λ)`.
SpectralBrdf ggx_conductor_brdf(float alpha, std::function<float(float)> reflectance);

} // namespace illum

// The MakeNamedMedium directive: pbrt-v4's media by "string type" ("homogeneous", "uniformgrid",
// "rgbgrid", "cloud", "nanovdb") from their parameters. Bad values (negative or non-finite coefficients,
// a grid of the wrong size, an unknown preset) throw illum::Error at the parameter's position.
#pragma once

#include <memory>
#include <string>

#include "illum/medium/medium.h"
#include "illum/medium/medium_spectrum.h"
#include "illum/param/entity.h"
#include "illum/radiometry/emission.h"
#include "illum/util/diagnostics.h"

namespace illum {

// What a medium reports about itself (illum info): its kind and the memory its data takes.
struct MediumInfo {
    std::string type;
    std::size_t bytes = 0;
};

struct CreatedMedium {
    std::unique_ptr<Medium> medium;
    MediumInfo info;
};

CreatedMedium create_medium(const MediumDesc& desc, Diagnostics& diag);

// Shared by the media's factories. A coefficient parameter (σ_a, σ_s: "rgb", "spectrum" or "blackbody";
// finite and non-negative), or `def` when absent.
MediumSpectrum medium_coefficient(const MediumDesc& desc, const std::string& name, Color3 def);
// The emitted radiance "Le" (an illuminant spectrum, as a light's L) times "Lescale"; black when absent.
// *emissive tells whether it is non-zero.
Emission medium_emission(const MediumDesc& desc, bool* emissive);
// "Le" alone, for a medium whose "Lescale" is not one float (uniformgrid: a grid); *nonzero as above.
Emission medium_le(const MediumDesc& desc, bool* nonzero);
// σ_a and σ_s from "preset" (a measured medium's name) when given, else from the parameters (default 1),
// each times "scale".
void medium_scattering(const MediumDesc& desc, MediumSpectrum* sigma_a, MediumSpectrum* sigma_s);
// The Henyey-Greenstein asymmetry "g", in (-1, 1).
float medium_g(const MediumDesc& desc);

// Grid media (grid_media.cpp): "uniformgrid", "rgbgrid", "cloud", "nanovdb"; null for another type.
CreatedMedium create_grid_medium(const MediumDesc& desc, Diagnostics& diag);

} // namespace illum

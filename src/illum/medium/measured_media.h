// Measured scattering coefficients of real materials, by pbrt-v4's preset names (a medium's "preset", a
// subsurface material's "name"; pbrt-v4's GetMediumScatteringProperties, src/pbrt/media.cpp): the 12 media
// of Jensen, Marschner, Levoy & Hanrahan 2001, "A Practical Model for Subsurface Light Transport"
// (SIGGRAPH; Apple ... Wholemilk: skin, marble, milk, ketchup...), and the 35 of Narasimhan, Gupta, Donner,
// Ramamoorthi, Nayar & Jensen 2006, "Acquiring Scattering Properties of Participating Media by Dilution"
// (SIGGRAPH; "Lowfat Milk" ... "Pacific Ocean Surface Water": milks, coffees, sodas, wines, juices,
// shampoos, powders). Names are case-sensitive and contain spaces, as in pbrt-v4.
//
// How pbrt-v4 uses them, and so do we:
// - Units: [mm^-1], used as they are, i.e. as per scene unit: pbrt-v4 does not rescale them (a scene in
//   metres needs "scale" 1000). Its homogeneous medium multiplies them by its "scale" (default 1), the
//   subsurface material by its "scale" (default 1).
// - σ_s: for Jensen's media the table holds the reduced scattering coefficient σ'_s = (1 - g) σ_s, and
//   pbrt-v4 uses it as σ_s. Its subsurface material therefore forces g = 0 with a "name" (warning when "g"
//   is non-zero); its homogeneous medium does not, and applies the "g" parameter (default 0) as given.
//   For Narasimhan's media the table holds σ_s itself (the paper's g is not kept).
// - Spectral mode: pbrt-v4 turns each RGB triple into an RGBUnboundedSpectrum in sRGB (MediumSpectrum's
//   UpliftKind::Unbounded).
// - Unknown names: pbrt-v4's medium warns and falls back to "sigma_a"/"sigma_s"; its subsurface material
//   stops with an error. Here measured_medium returns nullopt and the callers throw.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "illum/radiometry/color.h"

namespace illum {

struct MeasuredMedium {
    // [mm^-1] (read as per scene unit), sRGB-linear triples as pbrt-v4 tabulates them; sigma_s is the
    // reduced σ'_s for Jensen et al.'s media, σ_s for Narasimhan et al.'s.
    Color3 sigma_a, sigma_s;
};

std::optional<MeasuredMedium> measured_medium(std::string_view name);
const std::vector<std::string>& measured_medium_names();

} // namespace illum

// A lens prescription as pbrt-v4's realistic camera reads it ("lensfile"; PBR 4th ed. §5.3,
// scenes/lenses/*.dat): one surface per line, object side first, four numbers in millimetres,
//
//     curvature radius (0 = the aperture stop, a plane)   thickness to the next surface (the last: to
//     the film, replaced when focusing)   index of the medium after the surface (1 or 0 = air)
//     aperture diameter
//
// and '#' starting a comment. illum reads an optional fifth column, the Abbe number V_d of that medium
// (0 or absent: no dispersion); n is then n_d at 587.56 nm and varies with wavelength (cauchy_glass.h).
// A radius is positive when the centre of curvature lies on the film side of the surface (convex towards
// the object), as in optical design tables.
#pragma once

#include <string>
#include <vector>

#include "illum/util/error.h"

namespace illum {

struct LensSurfaceSpec {
    double radius_mm = 0, thickness_mm = 0, n_d = 1, aperture_mm = 0, abbe = 0;
    SourceLocation loc; // its line in the lens file
    bool is_stop() const { return radius_mm == 0; }
};

struct LensPrescription {
    std::vector<LensSurfaceSpec> surfaces; // object side first
    bool dispersive() const;               // any medium with V_d > 0
};

// Parses lens-file text; `name` positions errors (name:line:column). Throws illum::Error for a line that
// is not 4 or 5 numbers, a negative thickness, a non-positive aperture, an index in (0, 1) or an Abbe
// number on air, and for a file without surfaces.
LensPrescription parse_lens_file(const std::string& text, const std::string& name);
// Reads and parses a lens file; throws illum::Error naming it when it cannot be read.
LensPrescription read_lens_file(const std::string& path);

} // namespace illum

// Measured complex refractive indices η(λ) + i k(λ) of the materials pbrt-v4 names as
// "metal-<El>-eta" / "metal-<El>-k" (Ag, Al, Au, Cu, CuZn, MgO, TiO2). The numbers are in
// metal_spectra.cpp with their sources; this header only gives access to them.
#pragma once

#include <span>
#include <string_view>

#include "illum/radiometry/spectra.h"

namespace illum {

struct MeasuredIndex {
    std::string_view element;       // "Au", "CuZn", ...
    PiecewiseLinearSpectrum eta, k; // wavelength [nm] -> η, k; constant beyond the tabulated range
};

// Every measured index, in the order Ag, Al, Au, Cu, CuZn, MgO, TiO2. Built once, on first use.
std::span<const MeasuredIndex> measured_indices();
// The measured index of one element, or nullptr when it is not tabulated.
const MeasuredIndex* measured_index(std::string_view element);

} // namespace illum

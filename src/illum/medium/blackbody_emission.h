// The emission of a temperature grid (pbrt-v4's GridMedium and NanoVDBMedium with a "temperature" grid):
// pbrt-v4's BlackbodySpectrum(T), Planck's law normalised to 1 at its peak (blackbody_normalized), not to
// luminance 1 as a light's "blackbody" parameter, so a hotter voxel is brighter as well as bluer. Spectral
// mode evaluates it at the four wavelengths; RGB mode reads its linear sRGB (the XYZ of the spectrum, so
// luminance Y(T) and the chromaticity of blackbody_rgb) from a table log-spaced in T over [100 K, 10^6 K]
// (0.22% steps, linear in between: within 0.1% of the exact value above 800 K) and computes it exactly
// beyond the table.
#pragma once

#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

// T <= 100 K gives black (pbrt-v4: "if (temp > 100.f)").
SampledSpectrum blackbody_emission(float kelvin, const SampledWavelengths& w);
// RGB mode's value without the table (for the table and the tests).
Color3 blackbody_emission_rgb_exact(double kelvin);
// The table's size in bytes (once per process, shared by all media; built on first use).
std::size_t blackbody_table_bytes();

} // namespace illum

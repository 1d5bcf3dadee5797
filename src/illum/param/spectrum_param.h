// A spectrum-valued parameter ("spectrum L" [...], "blackbody L" [6500], "spectrum eta" "glass-BK7", or a
// file of (wavelength, value) pairs) reduced to RGB for RGB mode, or tabulated for spectral mode.
#pragma once

#include <memory>

#include "illum/param/param_set.h"
#include "illum/radiometry/color.h"
#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/util/diagnostics.h"

namespace illum {

enum class SpectrumKind {
    Unbounded,  // reflectance, η, k: XYZ of s·D65 normalised by D65's Y
    Illuminant, // emission: normalised to luminance 1 (pbrt-v4's "scale /= SpectrumToPhotometric")
};

// Named (pbrt-v4's metal, glass and illuminant names), blackbody (luminance 1), sampled (λ value pairs) or
// a file of such pairs (its name already resolved against the scene's folder by the parser). Marks the
// parameter used; throws illum::Error at its position for a bad spectrum or an unreadable file.
Color3 spectrum_param_rgb(const Param& p, SpectrumKind kind);

// Both modes' forms of the spectrum from one reading of the parameter (a file is read once): the RGB above
// and, for spectral mode, the spectrum tabulated at every nanometre: an illuminant normalised to luminance
// 1 (∫ s ȳ dλ = 1, pbrt-v4's photometric normalisation), anything else as given.
struct SpectrumParam {
    Color3 rgb;
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
};
SpectrumParam spectrum_param(const Param& p, SpectrumKind kind);

// A spectrum given for a scalar (an index of refraction "glass-BK7", say): for RGB mode the mean of its RGB
// reduction, which for pbrt-v4's named glasses is their index near 550 nm (any other spectrum but a
// dispersion formula is reported to `diag`, when given, as rendered with that mean), and its table.
struct ScalarSpectrumParam {
    float mean = 0;
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
};
ScalarSpectrumParam spectrum_param_scalar(const Param& p, Diagnostics* diag);

} // namespace illum

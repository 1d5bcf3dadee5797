// A spectrum-valued parameter ("spectrum L" [...], "blackbody L" [6500], "spectrum eta" "glass-BK7", or a
// file of (wavelength, value) pairs) reduced to RGB for RGB mode, or tabulated for spectral mode.
#pragma once

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

// The same spectrum for spectral mode, tabulated at every nanometre: an illuminant normalised to
// luminance 1 (∫ s ȳ dλ = 1, pbrt-v4's photometric normalisation), anything else as given.
DenselySampledSpectrum spectrum_param_dense(const Param& p, SpectrumKind kind);

// A spectrum given for a scalar (an index of refraction "glass-BK7", say) in an RGB render: the mean of its
// RGB reduction, which for pbrt-v4's named glasses is their index near 550 nm. Any other spectrum is
// reported to `diag` (when given) as rendered with that mean.
float spectrum_param_mean(const Param& p, Diagnostics* diag);

} // namespace illum

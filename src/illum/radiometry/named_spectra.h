// pbrt-v4's named spectra as full spectra, for the spectral mode (named_spectrum_rgb in spectra.h reduces
// them to RGB for the RGB mode):
//   glasses  "glass-BK7", "glass-BAF10", "glass-FK51A", "glass-LASF9", "glass-F5", "glass-F10",
//            "glass-F11": the index of refraction from the Schott Sellmeier coefficients (glass.h), sampled
//            at every 1 nm from 360 nm (or the first wavelength the coefficients are given for, if later)
//            to 830 nm, where linear interpolation is within 2e-6 of the formula;
//   metals   "metal-<El>-eta", "metal-<El>-k" for Ag, Al, Au, Cu, CuZn, MgO, TiO2: the measured indices of
//            metal_spectra.h as tabulated;
//   illuminants, each scaled to luminance 1 as pbrt-v4 scales them (Y of spectrum_to_xyz = 1):
//            "stdillum-A"   CIE illuminant A from its formula (cie_illuminant_a), at 1 nm, 300..830 nm;
//            "stdillum-D50" CIE D50: the daylight series at 5000 K nominal (5003 K, daylight.h), at the
//                           5 nm grid of S0, S1, S2 (pbrt-v4's table of this name is not D50: its
//                           chromaticity is (0.3368, 0.3580), D50's (0.3457, 0.3585));
//            "stdillum-D65" the CIE's table of D65 (cie_d65);
//            "stdillum-F1" .. "stdillum-F12" the CIE's tables of the fluorescent illuminants, 380..780 nm;
//            "illum-acesD60" the daylight formula at 6000 K (no c2 correction, so not the CIE's D60 of
//                           6003 K), whose chromaticity is the ACES white point (0.32168, 0.33767) of
//                           Academy TB-2018-001, as pbrt-v4 tabulates it.
// Every spectrum is constant beyond its first and last sample, as pbrt-v4 extends its named spectra.
// Not here: pbrt-v4's camera sensitivities ("canon_eos_100d_r", ... "sony_ilce_9_b"), Weta Digital
// measurements whose published form (the PhysLight data set) differs from the numbers pbrt-v4 carries.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "illum/radiometry/spectra.h"

namespace illum {

// The named spectrum, or nothing for an unknown name. Built once, on first use.
std::optional<PiecewiseLinearSpectrum> named_spectrum(std::string_view name);

// Every name named_spectrum knows, in pbrt-v4's order.
std::span<const std::string_view> named_spectrum_names();

} // namespace illum

// The CIE daylight illuminants (D-series) of any correlated colour temperature.
#pragma once

namespace illum {

// Relative spectral power of CIE daylight of correlated colour temperature cct_kelvin (4000..25000 K),
// normalised to 100 at 560 nm (CIE 15:2004 §3.1): D65 is cct 6504 K, ACES's "D60" 6000 K.
double cie_daylight(double lambda_nm, double cct_kelvin);

} // namespace illum

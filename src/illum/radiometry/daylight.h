// The CIE daylight series D_T: the relative spectral power of daylight of correlated colour
// temperature T from the components S0, S1, S2 (CIE 015:2004 "Colorimetry", 3rd ed., section 3; Judd,
// MacAdam and Wyszecki, J. Opt. Soc. Am. 54, 1031 (1964)):
//   x_D = -4.6070e9/T³ + 2.9678e6/T² + 0.09911e3/T + 0.244063   for 4000 K <= T <= 7000 K,
//   x_D = -2.0064e9/T³ + 1.9018e6/T² + 0.24748e3/T + 0.237040   for 7000 K <  T <= 25000 K,
//   y_D = -3.000 x_D² + 2.870 x_D - 0.275,
//   M  = 0.0241 + 0.2562 x_D - 0.7341 y_D,
//   M1 = (-1.3515 - 1.7703 x_D + 5.9114 y_D) / M,   M2 = (0.0300 - 31.4424 x_D + 30.0717 y_D) / M,
//   S_D(λ) = S0(λ) + M1 S1(λ) + M2 S2(λ),
// with M1 and M2 rounded to three decimals, as CIE 015:2004 prescribes so that the computed
// illuminants reproduce the CIE's tables (D50, D55, D75 to their printed precision, D65 to 8e-4 of 100).
#pragma once

#include "illum/radiometry/spectra.h"

namespace illum {

// The CIE's nominal temperatures (D50, D65...) are on the scale of c2 = 1.4380e-2 m K; on the present
// scale (c2 = 1.4388e-2 m K, since 1968) the correlated colour temperature is T · 1.4388 / 1.4380,
// so D65 is the daylight of 6504 K (6503.6) and D50 that of 5003 K.
constexpr double daylight_cct_of_nominal(double nominal_kelvin) { return nominal_kelvin * 1.4388 / 1.4380; }

struct DaylightCoefficients {
    double x, y;   // chromaticity x_D, y_D of the daylight locus
    double m1, m2; // weights of S1 and S2, rounded to three decimals
};
// The daylight locus and weights at correlated colour temperature T [K], T clamped to the range the CIE
// defines, 4000..25000 K.
DaylightCoefficients daylight_coefficients(double cct_kelvin);

// S_D(λ) at correlated colour temperature T [K] (clamped to 4000..25000 K): relative, 100 at 560 nm
// (where S0 = 100 and S1 = S2 = 0), linearly interpolated between the 5 nm samples of S0, S1, S2 and 0
// outside 300..830 nm. Callers normalise (pbrt-v4's white balance scales by 0.01 and, below 4000 K,
// uses a blackbody instead). Each call recomputes the coefficients: sample it once into a
// PiecewiseLinearSpectrum (at the 5 nm grid, exactly) for repeated use.
double cie_daylight(double lambda_nm, double cct_kelvin);

// pbrt-v4's illuminant for a film's "whitebalance" temperature T (Spectra::D): the daylight series at the
// correlated colour temperature daylight_cct_of_nominal(T), or, below 4000 K where the CIE defines no
// daylight, the blackbody of that temperature (blackbody_normalized). Only its chromaticity is meant to be
// used: the two branches are normalised differently (100 at 560 nm, peak 1). pbrt-v4 leaves M1, M2
// unrounded, which moves its spectrum by less than 0.03 (of 100) from this one.
double white_balance_illuminant(double lambda_nm, double nominal_kelvin);

} // namespace illum

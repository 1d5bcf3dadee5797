// The CIE's tabulated data as published, laid out one row per wavelength like the CIE's own tables:
// the 1931 colour-matching functions (cie_cmf_data.cpp), illuminant D65, the daylight components
// S0, S1, S2 and the fluorescent illuminants F1..F12 (cie_illuminant_data.cpp). Each .cpp names its
// source. The functions of spectra.h, daylight.h and named_spectra.h interpolate these tables; other
// code should call those rather than read the rows.
#pragma once

#include <array>

namespace illum::cie {

// CIE 1931 2° standard colorimetric observer, 1 nm steps from 360 to 830 nm.
inline constexpr int kCmfFirstNm = 360, kCmfLastNm = 830;
inline constexpr int kCmfCount = kCmfLastNm - kCmfFirstNm + 1; // 471
struct CmfRow {
    double x, y, z; // x̄(λ), ȳ(λ), z̄(λ)
};
extern const std::array<CmfRow, kCmfCount> kCmf1931;

// Illuminant D65 and the daylight components share one grid: 5 nm steps from 300 to 830 nm.
inline constexpr int kDaylightFirstNm = 300, kDaylightLastNm = 830, kDaylightStepNm = 5;
inline constexpr int kDaylightCount = (kDaylightLastNm - kDaylightFirstNm) / kDaylightStepNm + 1; // 107
extern const std::array<double, kDaylightCount> kD65; // relative, 100 at 560 nm
struct DaylightRow {
    double s0, s1, s2;
};
extern const std::array<DaylightRow, kDaylightCount> kDaylightComponents;

// Illuminants F1..F12 (fluorescent lamps), 5 nm steps from 380 to 780 nm; row i holds F1..F12 at
// 380 + 5 i nm.
inline constexpr int kFluorescentFirstNm = 380, kFluorescentLastNm = 780, kFluorescentStepNm = 5;
inline constexpr int kFluorescentCount =
    (kFluorescentLastNm - kFluorescentFirstNm) / kFluorescentStepNm + 1; // 81
inline constexpr int kFluorescentLamps = 12;
extern const std::array<std::array<double, kFluorescentLamps>, kFluorescentCount> kFluorescent;

} // namespace illum::cie

// Dispersion of dielectrics: the Sellmeier and Cauchy formulas, and the Schott glasses behind pbrt-v4's
// named spectra "glass-BK7", "glass-BAF10", "glass-FK51A", "glass-LASF9", "glass-F5", "glass-F10" and
// "glass-F11".
#pragma once

#include <span>
#include <string_view>

namespace illum {

// Sellmeier's formula (the form of the Schott catalogue): n²(λ) = 1 + Σ_i B_i λ² / (λ² - C_i), λ in µm,
// C_i in µm². Meaningful away from the resonances λ² = C_i (for optical glasses, within the catalogue's
// range, about 0.3..2.5 µm).
double sellmeier_index(double lambda_nm, const double B[3], const double C[3]);

// Cauchy's formula n(λ) = A + B / λ², λ in µm, B in µm².
double cauchy_index(double lambda_nm, double A, double B);

// A glass of the Schott catalogue (SCHOTT Zemax catalogue 2017-01-20, as refractiveindex.info lists it):
// Sellmeier coefficients and the wavelength range they are given for.
struct SchottGlass {
    std::string_view pbrt_name;   // "glass-BK7", ...
    std::string_view schott_name; // "N-BK7", ...
    double B[3], C[3];            // C in µm²
    double min_nm, max_nm;        // the range of validity of the coefficients
    double index(double lambda_nm) const { return sellmeier_index(lambda_nm, B, C); }
};

// The seven glasses pbrt-v4 names, in its order. pbrt-v4's tables are these Sellmeier formulas sampled at
// non-integer wavelengths and printed with the wavelengths rounded to integers (which shifts them by up
// to 0.5 nm, up to 4e-4 in n); its "glass-F5", "glass-F10" and "glass-F11" are the dense flints N-SF5,
// N-SF10 and N-SF11.
std::span<const SchottGlass> schott_glasses();
// The glass pbrt-v4 names `pbrt_name`, or nullptr.
const SchottGlass* schott_glass(std::string_view pbrt_name);

} // namespace illum

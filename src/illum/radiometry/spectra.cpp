#include "illum/radiometry/spectra.h"

#include <algorithm>
#include <cmath>

#include "illum/radiometry/cie_tables.h"

namespace illum {

namespace {

// Linear interpolation in a table sampled every `step` nm from `first` nm; 0 outside the table.
template <class Table, class Get>
double lerp_table(const Table& t, double first, double step, double l, Get get) {
    double u = (l - first) / step;
    int n = int(t.size());
    if (!(u >= 0 && u <= n - 1)) return 0; // also rejects NaN
    int i = std::min(int(u), n - 2);
    double f = u - i;
    return get(t[std::size_t(i)]) * (1 - f) + get(t[std::size_t(i + 1)]) * f;
}

double cmf(double l, double cie::CmfRow::*component) {
    return lerp_table(cie::kCmf1931, cie::kCmfFirstNm, 1, l,
                      [component](const cie::CmfRow& r) { return r.*component; });
}

// Planck's law with pbrt-v4's constants (CODATA 2010), λ in m.
constexpr double kC = 299792458.0, kH = 6.62606957e-34, kKb = 1.3806488e-23;
// x = h c / (λ_max k T) at the maximum of Planck's law in wavelength: the root of x = 5 (1 - e^-x).
constexpr double kWienX = 4.965114231744276;

} // namespace

double cie_x(double l) { return cmf(l, &cie::CmfRow::x); }
double cie_y(double l) { return cmf(l, &cie::CmfRow::y); }
double cie_z(double l) { return cmf(l, &cie::CmfRow::z); }

double cie_d65(double l) {
    return lerp_table(cie::kD65, cie::kDaylightFirstNm, cie::kDaylightStepNm, l, [](double v) { return v; });
}

double cie_illuminant_a(double l) {
    if (!(l > 0)) return 0;
    constexpr double c2 = 1.435e7, t = 2848; // nm K, K
    return 100 * std::pow(560 / l, 5) * std::expm1(c2 / (560 * t)) / std::expm1(c2 / (l * t));
}

double blackbody(double lambda_nm, double kelvin) {
    if (!(kelvin > 0)) return 0;
    double l = lambda_nm * 1e-9;
    return (2 * kH * kC * kC) / (std::pow(l, 5) * std::expm1((kH * kC) / (l * kKb * kelvin)));
}

double blackbody_normalized(double lambda_nm, double kelvin) {
    if (!(kelvin > 0)) return 0;
    double peak_nm = kH * kC / (kKb * kWienX * kelvin) * 1e9;
    return blackbody(lambda_nm, kelvin) / blackbody(peak_nm, kelvin);
}

double PiecewiseLinearSpectrum::operator()(double l) const {
    if (lambda.empty()) return 0;
    if (l <= lambda.front()) return value.front();
    if (l >= lambda.back()) return value.back();
    auto it = std::upper_bound(lambda.begin(), lambda.end(), l);
    std::size_t i = std::size_t(it - lambda.begin()) - 1;
    double f = (l - lambda[i]) / (lambda[i + 1] - lambda[i]);
    return value[i] * (1 - f) + value[i + 1] * f;
}

Color3 xyz_to_linear_srgb(double x, double y, double z) {
    return Color3(float(3.2404542 * x - 1.5371385 * y - 0.4985314 * z),
                  float(-0.9692660 * x + 1.8760108 * y + 0.0415560 * z),
                  float(0.0556434 * x - 0.2040259 * y + 1.0572252 * z));
}

namespace {
const Xyz& d65_xyz() {
    static const Xyz w = spectrum_to_xyz(cie_d65);
    return w;
}
// The RGB of D65 with luminance 1 through xyz_to_linear_srgb: (1, 1, 1) up to the rounding of the sRGB
// matrix and of the white point it assumes; dividing by it maps D65 (and a constant reflectance under it)
// exactly to grey.
Color3 d65_white() {
    static const Color3 white = xyz_to_linear_srgb(d65_xyz().x / d65_xyz().y, 1, d65_xyz().z / d65_xyz().y);
    return white;
}
} // namespace

Color3 unbounded_spectrum_to_rgb(const PiecewiseLinearSpectrum& s) {
    double y = d65_xyz().y;
    Xyz c = spectrum_to_xyz([&](double l) { return s(l) * cie_d65(l); });
    return xyz_to_linear_srgb(c.x / y, c.y / y, c.z / y) / d65_white();
}

Color3 illuminant_spectrum_to_rgb(const PiecewiseLinearSpectrum& s) {
    Xyz c = spectrum_to_xyz(s);
    if (!(c.y > 0)) return Color3(0.0f);
    return xyz_to_linear_srgb(c.x / c.y, 1, c.z / c.y) / d65_white();
}

Color3 blackbody_rgb(double kelvin) {
    PiecewiseLinearSpectrum s;
    for (int l = 360; l <= 830; l += 5) {
        s.lambda.push_back(l);
        s.value.push_back(blackbody(l, kelvin));
    }
    return illuminant_spectrum_to_rgb(s);
}

} // namespace illum

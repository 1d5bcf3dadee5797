#include "illum/radiometry/spectra.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "illum/radiometry/conductor_rgb.h"

namespace illum {

namespace {

// Wyman et al. 2013, eq. (2): a Gaussian with different widths left and right of its mean.
double lobe(double x, double mu, double s1, double s2) {
    double t = (x - mu) / (x < mu ? s1 : s2);
    return std::exp(-0.5 * t * t);
}

// CIE 15:2004 table: D65 relative spectral power distribution, 380..780 nm in 10 nm steps.
constexpr double kD65[] = {49.9755, 54.6482, 82.7549, 91.486,  93.4318, 86.6823, 104.865, 117.008, 117.812,
                           114.861, 115.923, 108.811, 109.354, 107.802, 104.790, 107.689, 104.405, 104.046,
                           100.000, 96.3342, 95.788,  88.6856, 90.0062, 89.5991, 87.6987, 83.2886, 83.6992,
                           80.0268, 80.2146, 82.2778, 78.2842, 69.7213, 71.6091, 74.349,  61.604,  69.8856,
                           75.087,  63.5927, 46.4182, 66.8054, 63.3828};

constexpr double kLambdaMin = 360, kLambdaMax = 830, kStep = 1;

struct Xyz {
    double x = 0, y = 0, z = 0;
};
template <class F>
Xyz integrate(F f) {
    Xyz r;
    for (double l = kLambdaMin; l <= kLambdaMax; l += kStep) {
        double v = f(l);
        r.x += v * cie_x(l);
        r.y += v * cie_y(l);
        r.z += v * cie_z(l);
    }
    return r;
}

} // namespace

double cie_x(double l) {
    return 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
           0.065 * lobe(l, 501.1, 20.4, 26.2);
}
double cie_y(double l) { return 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1); }
double cie_z(double l) { return 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8); }

double cie_d65(double l) {
    if (l < 380 || l > 780) return 0;
    double t = (l - 380) / 10;
    int i = std::min(int(t), 39);
    double f = t - i;
    return kD65[i] * (1 - f) + kD65[i + 1] * f;
}

double blackbody(double lambda_nm, double kelvin) {
    if (kelvin <= 0) return 0;
    constexpr double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
    double l = lambda_nm * 1e-9;
    return (2 * h * c * c) / (std::pow(l, 5) * (std::exp((h * c) / (l * kb * kelvin)) - 1));
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

Color3 unbounded_spectrum_to_rgb(const PiecewiseLinearSpectrum& s) {
    Xyz w = integrate([](double l) { return cie_d65(l); });
    Xyz c = integrate([&](double l) { return s(l) * cie_d65(l); });
    // Normalise by the white's own RGB so that a constant spectrum maps exactly to grey despite the
    // small error of the analytic fit.
    Color3 white = xyz_to_linear_srgb(w.x / w.y, 1, w.z / w.y);
    return xyz_to_linear_srgb(c.x / w.y, c.y / w.y, c.z / w.y) / white;
}

Color3 illuminant_spectrum_to_rgb(const PiecewiseLinearSpectrum& s) {
    Xyz w = integrate([](double l) { return cie_d65(l); });
    Xyz c = integrate([&](double l) { return s(l); });
    if (!(c.y > 0)) return Color3(0.0f);
    Color3 white = xyz_to_linear_srgb(w.x / w.y, 1, w.z / w.y);
    return xyz_to_linear_srgb(c.x / c.y, 1, c.z / c.y) / white;
}

Color3 blackbody_rgb(double kelvin) {
    PiecewiseLinearSpectrum s;
    for (double l = kLambdaMin; l <= kLambdaMax; l += 5) {
        s.lambda.push_back(l);
        s.value.push_back(blackbody(l, kelvin));
    }
    return illuminant_spectrum_to_rgb(s);
}

namespace {
struct NamedRgb {
    const char* name;
    Color3 rgb;
};
const NamedRgb kNamed[] = {
    // Glasses: the refractive index at 550 nm from the Schott Sellmeier coefficients (pbrt-v4 renders
    // their dispersion; an RGB renderer cannot). pbrt-v4 binds the names "glass-F5", "glass-F10" and
    // "glass-F11" to its tables of the dense flints SF5, SF10 and SF11, so they are those glasses here too.
    {"glass-BK7", Color3(1.5185f)},   {"glass-BAF10", Color3(1.6700f)}, {"glass-FK51A", Color3(1.4868f)},
    {"glass-LASF9", Color3(1.8503f)}, {"glass-F5", Color3(1.6755f)},    {"glass-F10", Color3(1.7331f)},
    {"glass-F11", Color3(1.7899f)},
};
} // namespace

bool is_illuminant_name(const std::string& name) { return name.rfind("stdillum-", 0) == 0; }

std::optional<Color3> named_spectrum_rgb(const std::string& name) {
    // "metal-<El>-eta" / "metal-<El>-k": the RGB index fitted to the measured spectra (conductor_rgb.h).
    if (name.rfind("metal-", 0) == 0) {
        std::string_view rest = std::string_view(name).substr(6);
        bool eta = rest.ends_with("-eta"), k = rest.ends_with("-k");
        if (!eta && !k) return std::nullopt;
        const ConductorRgb* c = named_conductor_rgb(rest.substr(0, rest.size() - (eta ? 4 : 2)));
        if (!c) return std::nullopt;
        return eta ? c->eta : c->k;
    }
    for (const NamedRgb& n : kNamed)
        if (name == n.name) return n.rgb;
    if (name == "stdillum-D65") return Color3(1.0f); // the sRGB white point, luminance 1
    if (name == "stdillum-A") return blackbody_rgb(2856);
    if (name == "stdillum-D50") return blackbody_rgb(5003); // approximated by the Planckian of its CCT
    return std::nullopt;
}

} // namespace illum

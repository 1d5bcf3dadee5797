// The four named colour spaces and their matrices. SMPTE RP 177-1993 (also Poynton, "Digital Video and
// HD", ch. 26): with the primaries' XYZ at Y = 1 as columns, P = [x/y, 1, (1-x-y)/y] per primary, and the
// white W (Y = 1), the scales S = P⁻¹ W make XYZ = P diag(S) RGB, so RGB (1, 1, 1) is the white.
// The white is the illuminant's own XYZ under the CMFs (integrate_spectrum), not a rounded chromaticity,
// so a constant reflectance under the illuminant is exactly grey.
#include "illum/radiometry/color_space.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "illum/math/matrix3.h"
#include "illum/radiometry/daylight.h"
#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

// The inverse of a colour space's matrix (never singular for real primaries).
Matrix3d invert(const Matrix3d& m) {
    std::optional<Matrix3d> inv = inverse(m);
    if (!inv) throw std::logic_error("singular colour space matrix");
    return *inv;
}

double d60(double lambda_nm) { return cie_daylight(lambda_nm, 6000); }

} // namespace

float RGBSigmoidPolynomial::max_value() const {
    // In double: with |c2| up to ~1e4 the float polynomial's rounding would blur the maximum.
    double a = c0, b = c1, c = c2;
    auto x = [&](double l) { return (a * l + b) * l + c; };
    double m = std::max(x(kSpectrumMinNm), x(kSpectrumMaxNm));
    if (a < 0) {
        double vertex = -b / (2 * a);
        if (vertex > kSpectrumMinNm && vertex < kSpectrumMaxNm) m = std::max(m, x(vertex));
    }
    return sigmoid(float(m));
}

RGBColorSpace::RGBColorSpace(std::string_view name, Chromaticity r, Chromaticity g, Chromaticity b,
                             Spectrum illuminant, int index)
    : name_(name), r_(r), g_(g), b_(b), illuminant_(illuminant), index_(index) {
    double y = integrate_spectrum([&](double l) { return illuminant_(l) * cie_y(l); });
    illuminant_scale_ = 1 / y;
    white_[0] = integrate_spectrum([&](double l) { return this->illuminant(l) * cie_x(l); });
    white_[1] = 1;
    white_[2] = integrate_spectrum([&](double l) { return this->illuminant(l) * cie_z(l); });

    const Chromaticity p[3] = {r, g, b};
    Matrix3d P;
    for (int c = 0; c < 3; ++c) {
        P[0 * 3 + c] = p[c].x / p[c].y;
        P[1 * 3 + c] = 1;
        P[2 * 3 + c] = (1 - p[c].x - p[c].y) / p[c].y;
    }
    const Matrix3d Pinv = invert(P);
    for (int c = 0; c < 3; ++c) {
        double s = Pinv[c * 3 + 0] * white_[0] + Pinv[c * 3 + 1] * white_[1] + Pinv[c * 3 + 2] * white_[2];
        for (int row = 0; row < 3; ++row) xyz_from_rgb_[row * 3 + c] = P[row * 3 + c] * s;
    }
    Matrix3d xyz_from_rgb;
    std::copy(xyz_from_rgb_, xyz_from_rgb_ + 9, xyz_from_rgb.begin());
    const Matrix3d rgb_from_xyz = invert(xyz_from_rgb);
    std::copy(rgb_from_xyz.begin(), rgb_from_xyz.end(), rgb_from_xyz_);
    for (int i = 0; i < 9; ++i) {
        rgb_from_xyz_f_[i] = float(rgb_from_xyz_[i]);
        xyz_from_rgb_f_[i] = float(xyz_from_rgb_[i]);
    }
}

const RGBColorSpace& RGBColorSpace::by_index(int i) {
    // sRGB / Rec. 709 (ITU-R BT.709), Rec. 2020 (ITU-R BT.2020), ACES2065-1 (SMPTE ST 2065-1, AP0 primaries,
    // white CIE daylight at 6000 K), DCI-P3 with the D65 white (P3-D65, as pbrt-v4 uses it).
    static const RGBColorSpace spaces[kCount] = {
        {"srgb", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, &cie_d65, 0},
        {"rec2020", {0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, &cie_d65, 1},
        {"aces2065-1", {0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.077}, &d60, 2},
        {"dci-p3", {0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}, &cie_d65, 3},
    };
    if (i < 0 || i >= kCount) throw std::out_of_range("RGBColorSpace::by_index");
    return spaces[i];
}

const RGBColorSpace* RGBColorSpace::named(std::string_view name) {
    for (int i = 0; i < kCount; ++i)
        if (by_index(i).name() == name) return &by_index(i);
    return nullptr;
}

const RGBColorSpace& RGBColorSpace::srgb() { return by_index(0); }

Color3 RGBColorSpace::rgb_from_xyz(double X, double Y, double Z) const {
    const double* m = rgb_from_xyz_;
    return Color3(float(m[0] * X + m[1] * Y + m[2] * Z), float(m[3] * X + m[4] * Y + m[5] * Z),
                  float(m[6] * X + m[7] * Y + m[8] * Z));
}

void RGBColorSpace::xyz_from_rgb(Color3 rgb, double xyz[3]) const {
    const double* m = xyz_from_rgb_;
    for (int row = 0; row < 3; ++row)
        xyz[row] = m[row * 3 + 0] * rgb.r + m[row * 3 + 1] * rgb.g + m[row * 3 + 2] * rgb.b;
}

} // namespace illum

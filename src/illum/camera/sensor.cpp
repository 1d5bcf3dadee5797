#include "illum/camera/sensor.h"

#include <algorithm>

#include "illum/math/matrix3.h"
#include "illum/radiometry/daylight.h"
#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

// The Bradford cone-response matrix (Lam 1985; CIE 159:2004 uses it in CIECAT02's predecessor).
constexpr Matrix3d kBradford = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};

// XYZ of the white-balance illuminant at Y = 1, integrated as the colour spaces integrate their whites.
std::array<double, 3> white_balance_xyz(double kelvin) {
    auto s = [&](double l) { return white_balance_illuminant(l, kelvin); };
    double x = integrate_spectrum([&](double l) { return s(l) * cie_x(l); }),
           y = integrate_spectrum([&](double l) { return s(l) * cie_y(l); }),
           z = integrate_spectrum([&](double l) { return s(l) * cie_z(l); });
    return {x / y, 1, z / y};
}

// von Kries adaptation in the Bradford space from white `src` to white `dst` (XYZ, Y = 1).
Matrix3d white_balance(const std::array<double, 3>& src, const std::array<double, 3>& dst) {
    double ls[3] = {0, 0, 0}, ld[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            ls[i] += kBradford[3 * i + k] * src[k];
            ld[i] += kBradford[3 * i + k] * dst[k];
        }
    Matrix3d d = {ld[0] / ls[0], 0, 0, 0, ld[1] / ls[1], 0, 0, 0, ld[2] / ls[2]};
    return multiply(*inverse(kBradford), multiply(d, kBradford));
}

} // namespace

Sensor::Sensor(const RGBColorSpace& output, float imaging_ratio, float white_balance_kelvin)
    : output_(&output), imaging_ratio_(imaging_ratio) {
    Matrix3d rgb_from_xyz, xyz_from_rgb;
    std::copy(output.rgb_from_xyz_matrix_f64(), output.rgb_from_xyz_matrix_f64() + 9, rgb_from_xyz.begin());
    std::copy(output.xyz_from_rgb_matrix_f64(), output.xyz_from_rgb_matrix_f64() + 9, xyz_from_rgb.begin());
    Matrix3d wb = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (white_balance_kelvin > 0) {
        const double* w = output.white_xyz(); // Y = 1
        wb = white_balance(white_balance_xyz(white_balance_kelvin), {w[0], w[1], w[2]});
    }
    Matrix3d m = multiply(rgb_from_xyz, wb);
    Matrix3d m_rgb = multiply(m, xyz_from_rgb);
    for (int i = 0; i < 9; ++i) {
        xyz_matrix_[i] = float(m[std::size_t(i)] * imaging_ratio);
        rgb_matrix_[i] = float(m_rgb[std::size_t(i)] * imaging_ratio);
        xyz_from_rgb_[i] = float(xyz_from_rgb[std::size_t(i)] * imaging_ratio);
    }
    identity_ = imaging_ratio == 1 && white_balance_kelvin <= 0;
    x_ = DenselySampledSpectrum::from([](double l) { return cie_x(l); });
    y_ = DenselySampledSpectrum::from([](double l) { return cie_y(l); });
    z_ = DenselySampledSpectrum::from([](double l) { return cie_z(l); });
}

} // namespace illum

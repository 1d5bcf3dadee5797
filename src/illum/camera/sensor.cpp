#include "illum/camera/sensor.h"

#include "illum/radiometry/daylight.h"
#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

using Mat3 = std::array<double, 9>;

Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return r;
}

Mat3 inverse(const Mat3& m) {
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                 m[2] * (m[3] * m[7] - m[4] * m[6]);
    Mat3 r = {m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
              m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
              m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
    for (double& x : r) x /= det;
    return r;
}

// The Bradford cone-response matrix (Lam 1985; CIE 159:2004 uses it in CIECAT02's predecessor).
constexpr Mat3 kBradford = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};

// XYZ of a spectrum's chromaticity at Y = 1.
std::array<double, 3> white_xyz(double (*s)(double, double), double param) {
    double x = 0, y = 0, z = 0;
    for (int l = 360; l <= 830; ++l) {
        double v = s(l, param);
        x += v * cie_x(l);
        y += v * cie_y(l);
        z += v * cie_z(l);
    }
    return {x / y, 1, z / y};
}

// von Kries adaptation in the Bradford space from white `src` to white `dst` (XYZ, Y = 1).
Mat3 white_balance(const std::array<double, 3>& src, const std::array<double, 3>& dst) {
    double ls[3] = {0, 0, 0}, ld[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) {
            ls[i] += kBradford[3 * i + k] * src[k];
            ld[i] += kBradford[3 * i + k] * dst[k];
        }
    Mat3 d = {ld[0] / ls[0], 0, 0, 0, ld[1] / ls[1], 0, 0, 0, ld[2] / ls[2]};
    return mul(inverse(kBradford), mul(d, kBradford));
}

} // namespace

Sensor::Sensor(const RGBColorSpace& output, float imaging_ratio, float white_balance_kelvin)
    : output_(&output), imaging_ratio_(imaging_ratio) {
    Mat3 rgb_from_xyz;
    for (int i = 0; i < 9; ++i) rgb_from_xyz[std::size_t(i)] = output.rgb_from_xyz_matrix()[i];
    Mat3 wb = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (white_balance_kelvin > 0) {
        std::array<double, 3> dst{};
        double xyz[3];
        output.xyz_from_rgb(Color3(1.0f), xyz);
        dst = {xyz[0] / xyz[1], 1, xyz[2] / xyz[1]};
        wb = white_balance(white_xyz(white_balance_illuminant, white_balance_kelvin), dst);
    }
    Mat3 m = mul(rgb_from_xyz, wb);
    Mat3 m_rgb = mul(m, inverse(rgb_from_xyz));
    for (int i = 0; i < 9; ++i) {
        xyz_matrix_[i] = float(m[std::size_t(i)] * imaging_ratio);
        rgb_matrix_[i] = float(m_rgb[std::size_t(i)] * imaging_ratio);
    }
    identity_ = imaging_ratio == 1 && white_balance_kelvin <= 0;
    x_ = DenselySampledSpectrum::from([](double l) { return cie_x(l); });
    y_ = DenselySampledSpectrum::from([](double l) { return cie_y(l); });
    z_ = DenselySampledSpectrum::from([](double l) { return cie_z(l); });
}

} // namespace illum

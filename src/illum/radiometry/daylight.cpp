// PROVISIONAL: replaced at merge (the daylight helper's implementation takes this file's place).
//
// CIE 15:2004 §3.1: S(λ) = S0(λ) + M1 S1(λ) + M2 S2(λ), with the chromaticity of the daylight locus
//   x_D = -4.6070e9/T³ + 2.9678e6/T² + 0.09911e3/T + 0.244063   (4000 K <= T <= 7000 K)
//   x_D = -2.0064e9/T³ + 1.9018e6/T² + 0.24748e3/T + 0.237040   (7000 K <  T <= 25000 K)
//   y_D = -3 x_D² + 2.870 x_D - 0.275
//   M1 = (-1.3515 - 1.7703 x_D + 5.9114 y_D) / M,  M2 = (0.0300 - 31.4424 x_D + 30.0717 y_D) / M,
//   M = 0.0241 + 0.2562 x_D - 0.7341 y_D,
// and the vectors S0, S1, S2 tabulated at 10 nm (CIE 15:2004 Table T.2), linearly interpolated here.
#include "illum/radiometry/daylight.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

// CIE 15:2004 Table T.2, 300..830 nm in 10 nm steps.
constexpr double kS0[] = {0.04,  6.0,   29.6,  55.3,  57.3,  61.8,  61.5,  68.8,  63.4,  65.8,  94.8,
                          104.8, 105.9, 96.8,  113.9, 125.6, 125.5, 121.3, 121.3, 113.5, 113.1, 110.8,
                          106.5, 108.8, 105.3, 104.4, 100.0, 96.0,  95.1,  89.1,  90.5,  90.3,  88.4,
                          84.0,  85.1,  81.9,  82.6,  84.9,  81.3,  71.9,  74.3,  76.4,  63.3,  71.7,
                          77.0,  65.2,  47.7,  68.6,  65.0,  66.0,  61.0,  53.3,  58.9,  61.9};
constexpr double kS1[] = {0.02,  4.5,   22.4,  42.0,  40.6,  41.6,  38.0,  42.4,  38.5,  35.0,  43.4,
                          46.3,  43.9,  37.1,  36.7,  35.9,  32.6,  27.9,  24.3,  20.1,  16.2,  13.2,
                          8.6,   6.1,   4.2,   1.9,   0.0,   -1.6,  -3.5,  -3.5,  -5.8,  -7.2,  -8.6,
                          -9.5,  -10.9, -10.7, -12.0, -14.0, -13.6, -12.0, -13.3, -12.9, -10.6, -11.6,
                          -12.2, -10.2, -7.8,  -11.2, -10.4, -10.6, -9.7,  -8.3,  -9.3,  -9.8};
constexpr double kS2[] = {0.0,  2.0,  4.0,  8.5,  7.8,  6.7,  5.3,  6.1,  3.0,  1.2,  -1.1, -0.5, -0.7, -1.2,
                          -2.6, -2.9, -2.8, -2.6, -2.6, -1.8, -1.5, -1.3, -1.2, -1.0, -0.5, -0.3, 0.0,  0.2,
                          0.5,  2.1,  3.2,  4.1,  4.7,  5.1,  6.7,  7.3,  8.6,  9.8,  10.2, 8.3,  9.6,  8.5,
                          7.0,  7.6,  8.0,  6.7,  5.2,  7.4,  6.8,  7.0,  6.4,  5.5,  6.1,  6.5};
constexpr int kCount = int(sizeof(kS0) / sizeof(kS0[0]));
constexpr double kFirstNm = 300, kStepNm = 10;

} // namespace

double cie_daylight(double lambda_nm, double cct_kelvin) {
    double t = (lambda_nm - kFirstNm) / kStepNm;
    if (!(t >= 0 && t <= kCount - 1)) return 0;
    int i = std::min(int(t), kCount - 2);
    double f = t - i;
    double T = std::clamp(cct_kelvin, 4000.0, 25000.0);
    double xd = T <= 7000 ? -4.6070e9 / (T * T * T) + 2.9678e6 / (T * T) + 0.09911e3 / T + 0.244063
                          : -2.0064e9 / (T * T * T) + 1.9018e6 / (T * T) + 0.24748e3 / T + 0.237040;
    double yd = -3 * xd * xd + 2.870 * xd - 0.275;
    double m = 0.0241 + 0.2562 * xd - 0.7341 * yd;
    double m1 = (-1.3515 - 1.7703 * xd + 5.9114 * yd) / m;
    double m2 = (0.0300 - 31.4424 * xd + 30.0717 * yd) / m;
    auto at = [&](int j) { return kS0[j] + m1 * kS1[j] + m2 * kS2[j]; };
    return at(i) * (1 - f) + at(i + 1) * f;
}

} // namespace illum

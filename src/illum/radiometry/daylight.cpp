#include "illum/radiometry/daylight.h"

#include <algorithm>
#include <cmath>

#include "illum/radiometry/cie_tables.h"

namespace illum {

DaylightCoefficients daylight_coefficients(double t) {
    t = std::clamp(t, 4000.0, 25000.0);
    double t2 = t * t, t3 = t2 * t;
    double x = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                         : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
    double y = -3.000 * x * x + 2.870 * x - 0.275;
    double m = 0.0241 + 0.2562 * x - 0.7341 * y;
    double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m;
    double m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m;
    return {x, y, std::round(m1 * 1000) / 1000, std::round(m2 * 1000) / 1000};
}

double cie_daylight(double l, double cct_kelvin) {
    double u = (l - cie::kDaylightFirstNm) / cie::kDaylightStepNm;
    constexpr int n = cie::kDaylightCount;
    if (!(u >= 0 && u <= n - 1)) return 0;
    DaylightCoefficients c = daylight_coefficients(cct_kelvin);
    int i = std::min(int(u), n - 2);
    double f = u - i;
    auto s = [&](int j) {
        const cie::DaylightRow& r = cie::kDaylightComponents[std::size_t(j)];
        return r.s0 + c.m1 * r.s1 + c.m2 * r.s2;
    };
    return s(i) * (1 - f) + s(i + 1) * f;
}

double white_balance_illuminant(double l, double nominal_kelvin) {
    double cct = daylight_cct_of_nominal(nominal_kelvin);
    return cct < 4000 ? blackbody_normalized(l, cct) : cie_daylight(l, cct);
}

} // namespace illum

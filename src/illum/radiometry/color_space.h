// PROVISIONAL (replaced at merge by the uplift branch): the API of RGB colour spaces and the
// Jakob-Hanika sigmoid polynomial.
#pragma once

#include <cmath>
#include <string_view>

#include "illum/radiometry/color.h"

namespace illum {

struct RGBSigmoidPolynomial {
    float c0 = 0, c1 = 0, c2 = 0;
    float operator()(float lambda_nm) const {
        float x = (c0 * lambda_nm + c1) * lambda_nm + c2;
        if (std::isinf(x)) return x > 0 ? 1.0f : 0.0f;
        return 0.5f + x / (2 * std::sqrt(1 + x * x));
    }
    float max_value() const;
};

class RGBColorSpace {
public:
    static const RGBColorSpace* named(std::string_view name);
    static const RGBColorSpace& srgb();
    std::string_view name() const;
    Color3 rgb_from_xyz(double X, double Y, double Z) const;
    void xyz_from_rgb(Color3 rgb, double xyz[3]) const;
    const float* rgb_from_xyz_matrix() const;
    double illuminant(double lambda_nm) const;
    RGBSigmoidPolynomial to_polynomial(Color3 rgb) const;
};

} // namespace illum

// PROVISIONAL (replaced at merge by the uplift branch): sRGB only, greys only.
#include "illum/radiometry/color_space.h"

#include "illum/radiometry/spectra.h"

namespace illum {

float RGBSigmoidPolynomial::max_value() const { return std::max((*this)(360), (*this)(830)); }

const RGBColorSpace& RGBColorSpace::srgb() {
    static RGBColorSpace s;
    return s;
}
const RGBColorSpace* RGBColorSpace::named(std::string_view name) { return name == "srgb" ? &srgb() : nullptr; }
std::string_view RGBColorSpace::name() const { return "srgb"; }
Color3 RGBColorSpace::rgb_from_xyz(double X, double Y, double Z) const { return xyz_to_linear_srgb(X, Y, Z); }
void RGBColorSpace::xyz_from_rgb(Color3, double xyz[3]) const { xyz[0] = xyz[1] = xyz[2] = 0; }
const float* RGBColorSpace::rgb_from_xyz_matrix() const {
    static const float m[9] = {3.2404542f, -1.5371385f, -0.4985314f, -0.9692660f, 1.8760108f,
                               0.0415560f, 0.0556434f,  -0.2040259f, 1.0572252f};
    return m;
}
double RGBColorSpace::illuminant(double l) const { return cie_d65(l) / 10567.0; }
RGBSigmoidPolynomial RGBColorSpace::to_polynomial(Color3 rgb) const {
    float v = std::clamp(rgb.average(), 1e-4f, 1 - 1e-4f);
    return {0, 0, (v - 0.5f) / std::sqrt(v * (1 - v))};
}

} // namespace illum

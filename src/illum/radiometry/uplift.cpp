#include "illum/radiometry/uplift.h"

#include <algorithm>
#include <array>

#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/rgb_to_spectrum.h"

namespace illum {

// Here rather than beside the tables (rgb_to_spectrum.cpp), so that each build compiles the lookup with its
// own instruction set: the tables' object is built once for both (cmake/rgb2spec.cmake).
RGBSigmoidPolynomial RGBColorSpace::to_polynomial(Color3 rgb) const {
    return rgb_to_spectrum_table(index_).lookup(rgb);
}

UpliftedRgb uplift_albedo_poly(Color3 rgb, const RGBColorSpace& cs) {
    return {cs.to_polynomial(clamp(rgb, 0.0f, 1.0f)), 1.0f};
}

UpliftedRgb uplift_unbounded_poly(Color3 rgb, const RGBColorSpace& cs) {
    rgb = Color3(std::max(rgb.r, 0.0f), std::max(rgb.g, 0.0f), std::max(rgb.b, 0.0f));
    float m = rgb.max_component();
    if (!(m > 0)) return {RGBSigmoidPolynomial{0, 0, -INFINITY}, 0.0f};
    // pbrt-v4's RGBUnboundedSpectrum: scale 2m, so the polynomial's colour has its maximum at 1/2, where
    // the sigmoid is most flexible.
    float scale = 2 * m;
    return {cs.to_polynomial(rgb / scale), scale};
}

SampledSpectrum illuminant_at(const RGBColorSpace& cs, const SampledWavelengths& w) {
    // Each space's illuminant tabulated at every nanometre, once (thread-safe static initialisation).
    static const auto tables = [] {
        std::array<DenselySampledSpectrum, RGBColorSpace::kCount> t;
        for (int i = 0; i < RGBColorSpace::kCount; ++i) {
            const RGBColorSpace& c = RGBColorSpace::by_index(i);
            t[std::size_t(i)] = DenselySampledSpectrum::from([&](double l) { return c.illuminant(l); });
        }
        return t;
    }();
    return tables[std::size_t(cs.index())].sample(w);
}

} // namespace illum

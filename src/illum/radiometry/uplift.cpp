#include "illum/radiometry/uplift.h"

#include <algorithm>

#include "illum/radiometry/densely_sampled_spectrum.h"

namespace illum {

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
    // One table per colour space, built on first use (thread-safe static initialisation).
    struct Tables {
        const RGBColorSpace* cs;
        DenselySampledSpectrum d;
    };
    static const Tables tables[] = {
        {RGBColorSpace::named("srgb"), {}}, {RGBColorSpace::named("rec2020"), {}},
        {RGBColorSpace::named("aces2065-1"), {}}, {RGBColorSpace::named("dci-p3"), {}}};
    static const DenselySampledSpectrum dense[] = {
        DenselySampledSpectrum::from([](double l) { return tables[0].cs->illuminant(l); }),
        DenselySampledSpectrum::from([](double l) { return tables[1].cs->illuminant(l); }),
        DenselySampledSpectrum::from([](double l) { return tables[2].cs->illuminant(l); }),
        DenselySampledSpectrum::from([](double l) { return tables[3].cs->illuminant(l); })};
    for (int i = 0; i < 4; ++i)
        if (tables[i].cs == &cs) return dense[i].sample(w);
    return DenselySampledSpectrum::from([&](double l) { return cs.illuminant(l); }).sample(w);
}

} // namespace illum

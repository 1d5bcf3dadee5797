#include "illum/medium/textured_subsurface_medium.h"

#include <algorithm>

#include "illum/medium/subsurface_coefficients.h"

namespace illum {

SampledSpectrum SubsurfaceParam::at(const TextureEvalContext& ctx, const SampledWavelengths& lambda,
                                    UpliftKind kind) const {
    if (spectrum && lambda.spectral()) return spectrum->sample(lambda);
    return kind == UpliftKind::Albedo ? texture->albedo(ctx, lambda) : texture->unbounded(ctx, lambda);
}

std::unique_ptr<TexturedSubsurfaceMedium>
TexturedSubsurfaceMedium::from_sigma(SubsurfaceParam sigma_a, SubsurfaceParam sigma_s, float scale, float g) {
    return std::unique_ptr<TexturedSubsurfaceMedium>(
        new TexturedSubsurfaceMedium(std::move(sigma_a), std::move(sigma_s), scale, g, nullptr));
}

std::unique_ptr<TexturedSubsurfaceMedium>
TexturedSubsurfaceMedium::from_reflectance(SubsurfaceParam reflectance, SubsurfaceParam mfp, float scale,
                                           float eta, float g) {
    return std::unique_ptr<TexturedSubsurfaceMedium>(new TexturedSubsurfaceMedium(
        std::move(reflectance), std::move(mfp), scale, g, std::make_unique<EffectiveAlbedoTable>(eta, g)));
}

void TexturedSubsurfaceMedium::evaluate(const TextureEvalContext& at, const SampledWavelengths& lambda,
                                        EntryMedium* out) const {
    SampledSpectrum sigma_a, sigma_s;
    if (!table_) {
        // σ = max(0, scale · value), as pbrt-v4's GetBSSRDF.
        sigma_a = a_.at(at, lambda, UpliftKind::Unbounded) * scale_;
        sigma_s = b_.at(at, lambda, UpliftKind::Unbounded) * scale_;
        for (int i = 0; i < kSpectrumSamples; ++i) {
            sigma_a[i] = std::max(sigma_a[i], 0.0f);
            sigma_s[i] = std::max(sigma_s[i], 0.0f);
        }
    } else {
        SampledSpectrum rho = a_.at(at, lambda, UpliftKind::Albedo);
        SampledSpectrum mfp = b_.at(at, lambda, UpliftKind::Unbounded);
        // Spectral mode: the wavelengths; RGB mode: the channels (the fourth lane repeats green).
        for (int i = 0; i < kSpectrumSamples; ++i) {
            SubsurfaceCoefficient c = subsurface_from_reflectance_value(rho[i], mfp[i], scale_, *table_);
            sigma_a[i] = c.sigma_a;
            sigma_s[i] = c.sigma_s;
        }
    }
    out->set(*this, sigma_a, sigma_s, HenyeyGreenstein{g_});
}

MediumProperties TexturedSubsurfaceMedium::sample_point(Point3f p, const SampledWavelengths& lambda) const {
    TextureEvalContext at;
    at.p = p;
    EntryMedium m;
    evaluate(at, lambda, &m);
    return m.sample_point(p, lambda);
}

MajorantIterator TexturedSubsurfaceMedium::sample_ray(const Ray& ray, float tmax,
                                                      const SampledWavelengths& lambda) const {
    MediumProperties mp = sample_point(ray.o, lambda);
    return MajorantIterator::single(0, tmax, mp.sigma_a + mp.sigma_s);
}

} // namespace illum

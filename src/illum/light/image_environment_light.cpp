#include "illum/light/image_environment_light.h"

#include "illum/radiometry/uplift.h"

#include "illum/math/warp.h"

namespace illum {

ImageEnvironmentLight::ImageEnvironmentLight(EnvironmentMap map, const Transform& world_from_light,
                                             float scale, EnvSampling sampling)
    : Light(LightType::Infinite), map_(std::move(map)), world_from_light_(world_from_light),
      light_from_world_(world_from_light.inverse()), scale_(std::isfinite(scale) && scale > 0 ? scale : 0.0f),
      sampling_(sampling) {
    int w = map_.width(), h = map_.height();
    const auto& sa = map_.solid_angles();
    std::vector<float> weights(std::size_t(w) * h);
    double total = 0, sum[3] = {0, 0, 0};
    std::size_t valid = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        Color3 c = map_.image().data()[i];
        for (int k = 0; k < 3; ++k) sum[k] += double(c[k]) * sa[i];
        weights[i] = c.average() * sa[i];
        total += weights[i];
        valid += sa[i] > 0;
    }
    integral_ = Color3(float(sum[0]), float(sum[1]), float(sum[2]));
    if (total > 0 && valid > 0) {
        float floor = float(1e-3 * total / double(valid));
        for (std::size_t i = 0; i < weights.size(); ++i)
            if (sa[i] > 0) weights[i] += floor * sa[i] / float(4 * kPiD / double(valid));
    } else {
        // Zero-energy map: uniform by solid angle.
        for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = sa[i];
    }
    distribution_ = Distribution2D(weights, w, h);
}

void ImageEnvironmentLight::preprocess(const Bounds3f& scene_bounds) {
    scene_bounds.bounding_sphere(&scene_center_, &scene_radius_);
}

Radiance3 ImageEnvironmentLight::radiance(Vector3f w, const SampledWavelengths& lambda) const {
    Vector3f d = light_from_world_(w);
    float len = length(d);
    if (!(len > 0)) return {};
    return Radiance3(uplift_illuminant(map_.lookup(d / len), lambda) * scale_);
}

float ImageEnvironmentLight::pdf_light_space(Vector3f d) const {
    Point2f uv = env_uv(map_.layout(), d);
    float j = env_jacobian(map_.layout(), uv);
    if (!(j > 0)) return 0;
    return distribution_.pdf(uv) / j;
}

std::optional<LightLiSample> ImageEnvironmentLight::sample_li(const LightSampleContext&, Point2f u,
                                                              const SampledWavelengths& lambda) const {
    Vector3f wi;
    SolidAnglePdf pdf;
    switch (sampling_) {
    case EnvSampling::None:
        return std::nullopt;
    case EnvSampling::Uniform:
        wi = sample_uniform_sphere(u);
        pdf = SolidAnglePdf(uniform_sphere_pdf());
        break;
    case EnvSampling::Importance: {
        float pdf_uv = 0;
        Point2f uv = distribution_.sample(u, &pdf_uv);
        float j = env_jacobian(map_.layout(), uv);
        auto d = env_direction(map_.layout(), uv);
        if (!d || !(pdf_uv > 0) || !(j > 0)) return std::nullopt;
        wi = normalize(world_from_light_(*d));
        pdf = SolidAnglePdf(pdf_uv / j);
        break;
    }
    }
    Radiance3 l = radiance(wi, lambda);
    if (l.is_black() || !(pdf > SolidAnglePdf(0)) || !pdf.is_finite()) return std::nullopt;
    return LightLiSample{wi, l, biradiance(l, pdf), pdf, {}, {}, {}, true};
}

SolidAnglePdf ImageEnvironmentLight::pdf_li(const LightSampleContext&, Vector3f wi, const SurfaceHit*) const {
    switch (sampling_) {
    case EnvSampling::None:
        return SolidAnglePdf(0);
    case EnvSampling::Uniform:
        return SolidAnglePdf(uniform_sphere_pdf());
    case EnvSampling::Importance:
        break;
    }
    Vector3f d = light_from_world_(wi);
    float len = length(d);
    if (!(len > 0)) return SolidAnglePdf(0);
    return SolidAnglePdf(pdf_light_space(d / len));
}

Power3 ImageEnvironmentLight::power() const {
    return Power3(SampledSpectrum(integral_ * (scale_ * kPi * scene_radius_ * scene_radius_)));
}

float ImageEnvironmentLight::upper_hemisphere_irradiance() const {
    const auto& sa = map_.solid_angles();
    double e = 0;
    for (int y = 0; y < map_.height(); ++y)
        for (int x = 0; x < map_.width(); ++x) {
            auto d = map_.texel_direction(x, y);
            if (!d || d->z <= 0) continue;
            e += double(map_.texel(x, y).luminance()) * d->z * sa[std::size_t(y) * map_.width() + x];
        }
    return float(e);
}

std::optional<LightLeSample> ImageEnvironmentLight::sample_le(Point2f u1, Point2f u2,
                                                              const SampledWavelengths& lambda) const {
    if (!(scene_radius_ > 0)) return std::nullopt;
    // The map's own distribution whatever the sampling mode: photons follow the light.
    float pdf_uv = 0;
    Point2f uv = distribution_.sample(u2, &pdf_uv);
    float j = env_jacobian(map_.layout(), uv);
    auto d = env_direction(map_.layout(), uv);
    if (!d || !(pdf_uv > 0) || !(j > 0)) return std::nullopt;
    Vector3f wi = normalize(world_from_light_(*d));
    Radiance3 l = radiance(wi, lambda);
    if (l.is_black()) return std::nullopt;
    return disk_emission(scene_center_, scene_radius_, wi, u1, l, SolidAnglePdf(pdf_uv / j));
}

void ImageEnvironmentLight::pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = disk_emission_pdf(scene_radius_);
    Vector3f d = light_from_world_(-ray.d);
    float len = length(d);
    *dir = SolidAnglePdf(len > 0 ? pdf_light_space(d / len) : 0.0f);
}

} // namespace illum

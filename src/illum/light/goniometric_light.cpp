#include "illum/light/goniometric_light.h"

#include <algorithm>

#include "illum/envmap/layout.h"
#include "illum/light/point_source.h"

namespace illum {

GoniometricLight::GoniometricLight(const Transform& world_from_light, Emission intensity, const Image& image)
    : Light(LightType::DeltaPosition), position_(world_from_light(Point3f{0, 0, 0})),
      world_from_light_(world_from_light), light_from_world_(world_from_light.inverse()),
      intensity_(std::move(intensity)), n_(image.width()) {
    y_.resize(image.pixel_count());
    double sum = 0;
    for (std::size_t i = 0; i < y_.size(); ++i) {
        y_[i] = std::max(image.data()[i].average(), 0.0f);
        sum += y_[i];
    }
    mean_y_ = y_.empty() ? 0.0 : sum / double(y_.size());
    distribution_ = Distribution2D(y_, image.width(), image.height());
}

Vector3f GoniometricLight::image_from_world(Vector3f w) const {
    Vector3f l = normalize(light_from_world_(w));
    return {l.x, l.z, l.y};
}

Vector3f GoniometricLight::world_from_image(Vector3f d) const {
    return normalize(world_from_light_(Vector3f{d.x, d.z, d.y}));
}

float GoniometricLight::relative_intensity(Vector3f d) const {
    Point2f uv = env_uv(EnvLayout::Octahedral, d);
    int x = std::clamp(int(uv.x * float(n_)), 0, n_ - 1), y = std::clamp(int(uv.y * float(n_)), 0, n_ - 1);
    return y_[std::size_t(y) * std::size_t(n_) + std::size_t(x)];
}

Intensity3 GoniometricLight::intensity(Vector3f w_world, const SampledWavelengths& lambda) const {
    float y = relative_intensity(image_from_world(w_world));
    if (y == 0) return {};
    return Intensity3(intensity_.at(lambda) * y);
}

std::optional<LightLiSample> GoniometricLight::sample_li(const LightSampleContext& ctx, Point2f,
                                                         const SampledWavelengths& lambda) const {
    return point_source_li(position_, ctx.p, [&](Vector3f w) { return intensity(w, lambda); });
}

Power3 GoniometricLight::power() const {
    return Intensity3(intensity_.rgb_value()) * SolidAngle(float(4 * kPiD * mean_y_));
}

std::optional<LightLeSample> GoniometricLight::sample_le(Point2f, Point2f u2,
                                                         const SampledWavelengths& lambda) const {
    float pdf_uv = 0;
    Point2f uv = distribution_.sample(u2, &pdf_uv);
    auto d = env_direction(EnvLayout::Octahedral, uv);
    if (!d || !(pdf_uv > 0)) return std::nullopt;
    Vector3f w = world_from_image(*d);
    SolidAnglePdf pdf_dir(pdf_uv / (4 * kPi));
    return LightLeSample{Ray{position_, w}, {}, {}, AreaPdf(1), pdf_dir, intensity(w, lambda) / pdf_dir,
                         position_,         {}};
}

void GoniometricLight::pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = AreaPdf(1);
    Point2f uv = env_uv(EnvLayout::Octahedral, image_from_world(ray.d));
    *dir = SolidAnglePdf(distribution_.pdf(uv) / (4 * kPi));
}

} // namespace illum

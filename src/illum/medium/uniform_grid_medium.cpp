#include "illum/medium/uniform_grid_medium.h"

#include "illum/medium/blackbody_emission.h"

namespace illum {

UniformGridMedium::UniformGridMedium(UniformGridParams p)
    : p_(std::move(p)),
      // pbrt-v4 GridMedium: emissive with a temperature grid, else when Le is non-zero.
      emissive_(p_.temperature ? true : p_.le_nonzero),
      majorant_(build_majorant_grid({16, 16, 16}, [&](const Bounds3f& b) {
          return p_.density.max_value(b, [](float v) { return v; });
      })) {}

std::size_t UniformGridMedium::bytes() const {
    std::size_t b = p_.density.bytes() + p_.le_scale.bytes() + majorant_.bytes();
    if (p_.temperature) b += p_.temperature->bytes() + blackbody_table_bytes();
    return b;
}

MediumProperties UniformGridMedium::sample_point(Point3f p, const SampledWavelengths& lambda) const {
    Point3f u = p_.box.unit_point(p);
    float d = p_.density.lookup(u);
    MediumProperties mp{p_.sigma_a.at(lambda) * d, p_.sigma_s.at(lambda) * d, HenyeyGreenstein{p_.g},
                        SampledSpectrum(0.0f)};
    if (emissive_) {
        float scale = p_.le_scale.lookup(u);
        if (scale > 0) {
            if (p_.temperature) {
                float t = (p_.temperature->lookup(u) - p_.temperature_offset) * p_.temperature_scale;
                mp.le = blackbody_emission(t, lambda) * scale;
            } else {
                mp.le = p_.le.at(lambda) * scale;
            }
        }
    }
    return mp;
}

MajorantIterator UniformGridMedium::sample_ray(const Ray& ray, float tmax,
                                               const SampledWavelengths& lambda) const {
    Point3f o;
    Vector3f d;
    float t0, t1;
    if (!p_.box.clip(ray, tmax, &o, &d, &t0, &t1)) return {};
    return MajorantIterator::dda(&majorant_, o, d, t0, t1, p_.sigma_a.at(lambda) + p_.sigma_s.at(lambda));
}

} // namespace illum

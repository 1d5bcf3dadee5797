#include "illum/medium/rgb_grid_medium.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "illum/radiometry/uplift.h"

namespace illum {

namespace {

// The largest value a sample's σ takes in RGB mode or, uplifted, in any colour space's spectral mode.
float sample_bound(Color3 c) {
    float m = std::max({c.r, c.g, c.b, 0.0f});
    if (c.r == c.g && c.g == c.b) return m; // a grey uplifts to a constant spectrum
    for (int i = 0; i < RGBColorSpace::kCount; ++i) {
        UpliftedRgb u = uplift_unbounded_poly(c, RGBColorSpace::by_index(i));
        m = std::max(m, u.scale * u.poly.max_value());
    }
    return m;
}

std::optional<SampledGrid<float>> bounds_of(const std::optional<SampledGrid<Color3>>& g) {
    if (!g) return std::nullopt;
    std::vector<float> b(g->values().size());
    // Up to four table lookups per sample: in parallel for a large grid.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, b.size(), 4096), [&](const auto& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) b[i] = sample_bound(g->values()[i]);
    });
    return SampledGrid<float>(std::move(b), g->nx(), g->ny(), g->nz());
}

} // namespace

RGBGridMedium::RGBGridMedium(RGBGridParams p)
    : p_(std::move(p)), bound_a_(bounds_of(p_.sigma_a)), bound_s_(bounds_of(p_.sigma_s)),
      majorant_(build_majorant_grid({16, 16, 16}, [&](const Bounds3f& b) {
          auto id = [](float v) { return v; };
          float a = bound_a_ ? bound_a_->max_value(b, id) : 1.0f;
          float s = bound_s_ ? bound_s_->max_value(b, id) : 1.0f;
          return p_.scale * (a + s);
      })) {
    // The per-sample bounds served only to build the majorant grid.
    bound_a_.reset();
    bound_s_.reset();
}

std::size_t RGBGridMedium::bytes() const {
    std::size_t b = majorant_.bytes();
    for (const auto* g : {&p_.sigma_a, &p_.sigma_s, &p_.le})
        if (*g) b += (*g)->bytes();
    return b;
}

MediumProperties RGBGridMedium::sample_point(Point3f p, const SampledWavelengths& lambda) const {
    Point3f u = p_.box.unit_point(p);
    auto coefficient = [&](const std::optional<SampledGrid<Color3>>& g) {
        if (!g) return SampledSpectrum(1.0f);
        if (!lambda.spectral()) return SampledSpectrum(g->lookup(u));
        const RGBColorSpace& cs = *lambda.color_space;
        return g->lookup(u, [&](Color3 c) { return sample(uplift_unbounded_poly(c, cs), lambda); });
    };
    MediumProperties mp{coefficient(p_.sigma_a) * p_.scale, coefficient(p_.sigma_s) * p_.scale,
                        HenyeyGreenstein{p_.g}, SampledSpectrum(0.0f)};
    if (is_emissive()) {
        // An illuminant uplift is the unbounded one times the colour space's illuminant, a factor common to
        // the eight samples.
        mp.le = coefficient(p_.le) * p_.le_scale;
        if (lambda.spectral()) mp.le *= illuminant_at(*lambda.color_space, lambda);
    }
    return mp;
}

MajorantIterator RGBGridMedium::sample_ray(const Ray& ray, float tmax, const SampledWavelengths&) const {
    Point3f o;
    Vector3f d;
    float t0, t1;
    if (!p_.box.clip(ray, tmax, &o, &d, &t0, &t1)) return {};
    return MajorantIterator::dda(&majorant_, o, d, t0, t1, SampledSpectrum(1.0f));
}

} // namespace illum

// pbrt-v4's "homogeneous" medium: σ_a, σ_s, g and Le the same everywhere (unbounded; the shapes whose
// MediumInterface names it bound it). Its majorant is σ_t itself, so delta tracking never meets a null
// collision and ratio tracking is exact: transmittance exp(-σ_t d).
#pragma once

#include "illum/medium/medium.h"
#include "illum/medium/medium_spectrum.h"
#include "illum/radiometry/emission.h"

namespace illum {

class HomogeneousMedium final : public Medium {
public:
    HomogeneousMedium(MediumSpectrum sigma_a, MediumSpectrum sigma_s, float g, Emission le, bool emissive)
        : sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), le_(std::move(le)), g_(g),
          emissive_(emissive) {}

    bool is_emissive() const override { return emissive_; }
    bool is_homogeneous() const override { return true; }
    MediumProperties sample_point(Point3f, const SampledWavelengths& lambda) const override {
        return {sigma_a_.at(lambda), sigma_s_.at(lambda), HenyeyGreenstein{g_},
                emissive_ ? le_.at(lambda) : SampledSpectrum()};
    }
    MajorantIterator sample_ray(const Ray&, float tmax, const SampledWavelengths& lambda) const override {
        return MajorantIterator::single(0, tmax, sigma_a_.at(lambda) + sigma_s_.at(lambda));
    }
    const MediumSpectrum& sigma_a() const { return sigma_a_; }
    const MediumSpectrum& sigma_s() const { return sigma_s_; }
    float g() const { return g_; }

private:
    MediumSpectrum sigma_a_, sigma_s_;
    Emission le_;
    float g_;
    bool emissive_;
};

} // namespace illum

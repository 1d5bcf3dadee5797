// A medium's coefficient (σ_a, σ_s) in both modes: RGB mode's value, and for spectral mode either the
// spectrum the scene gave or the RGB uplifted as an unbounded spectrum (as pbrt-v4's
// RGBUnboundedSpectrum), times a scale. Constant over the medium; grids multiply it by their density.
#pragma once

#include <array>
#include <memory>

#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/uplift.h"

namespace illum {

class MediumSpectrum {
public:
    MediumSpectrum() = default;
    explicit MediumSpectrum(Color3 rgb) : rgb_(rgb), uplifted_(rgb, UpliftKind::Unbounded) {}
    MediumSpectrum(Color3 rgb, std::shared_ptr<const DenselySampledSpectrum> s)
        : rgb_(rgb), spectrum_(std::move(s)) {}
    // A spectrum that depends on the colour space RGB inputs are given in (derived from uplifted inputs:
    // a subsurface material's coefficients from its reflectance), tabulated for each.
    using PerColorSpace = std::array<DenselySampledSpectrum, RGBColorSpace::kCount>;
    MediumSpectrum(Color3 rgb, std::shared_ptr<const PerColorSpace> s)
        : rgb_(rgb), per_space_(std::move(s)) {}

    SampledSpectrum at(const SampledWavelengths& w) const {
        if (!w.spectral()) return SampledSpectrum(rgb_ * scale_);
        if (per_space_) return (*per_space_)[std::size_t(w.color_space->index())].sample(w) * scale_;
        return (spectrum_ ? spectrum_->sample(w) : uplifted_.at(w)) * scale_;
    }
    Color3 rgb() const { return rgb_ * scale_; }
    MediumSpectrum& operator*=(float s) {
        scale_ *= s;
        return *this;
    }

private:
    Color3 rgb_{0.0f};
    UpliftCache uplifted_;
    std::shared_ptr<const DenselySampledSpectrum> spectrum_;
    std::shared_ptr<const PerColorSpace> per_space_;
    float scale_ = 1;
};

} // namespace illum

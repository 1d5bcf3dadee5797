// pbrt-v4's "rgbgrid" medium (RGBGridMedium; pbrt-v4 media.h/.cpp): σ_a, σ_s and Le given per sample as
// RGB grids over the box [p0, p1] (sampled_grid.h), times "scale" (σ) and "Lescale" (Le). A missing σ grid
// is 1 everywhere (times scale). In spectral mode each of the eight samples around a point is uplifted
// (σ as an unbounded spectrum, Le as an illuminant one) and the spectra are interpolated, as pbrt-v4
// interpolates its RGBUnboundedSpectrum / RGBIlluminantSpectrum samples; in RGB mode the RGB values are.
// The majorant grid (16^3) holds scale · (max σ_a + max σ_s) over each voxel's influencing samples, each
// sample's bound being the largest of its RGB components and of its uplifted spectrum's maximum in every
// colour space (pbrt-v4 takes the spectrum's MaxValue in the scene's one colour space; the colour space
// here is the render's, so the bound covers them all); the ray's σ_t factor is 1.
#pragma once

#include <optional>

#include "illum/medium/medium.h"
#include "illum/medium/medium_box.h"
#include "illum/medium/sampled_grid.h"

namespace illum {

struct RGBGridParams {
    MediumBox box;
    float g = 0;
    std::optional<SampledGrid<Color3>> sigma_a, sigma_s, le;
    float scale = 1, le_scale = 1;
};

class RGBGridMedium final : public Medium {
public:
    explicit RGBGridMedium(RGBGridParams p);

    bool is_emissive() const override { return p_.le && p_.le_scale > 0; }
    MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const override;
    MajorantIterator sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const override;

    const MajorantGrid& majorant_grid() const { return majorant_; }
    std::size_t bytes() const;

private:
    RGBGridParams p_;
    // Per sample, the bound on σ_a (resp. σ_s) over both modes and all colour spaces.
    std::optional<SampledGrid<float>> bound_a_, bound_s_;
    MajorantGrid majorant_;
};

} // namespace illum

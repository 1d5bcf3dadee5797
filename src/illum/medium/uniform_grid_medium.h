// pbrt-v4's "uniformgrid" medium (GridMedium; pbrt-v4 media.h/.cpp, PBR 4th ed. §11.4.3): a density grid
// (sampled_grid.h) over the box [p0, p1] of medium space scales σ_a and σ_s; the emission is either "Le"
// (an illuminant spectrum, normalised to luminance 1) or, with a "temperature" grid, the peak-normalised
// blackbody of (T - temperatureoffset) · temperaturescale, each times the "Lescale" grid (one sample of
// 1 when absent: with SampledGrid's fall-off that is a tent, 1 at the centre and 1/8 at the corners, as in
// pbrt-v4). The majorant grid (16^3, as pbrt-v4) holds each voxel's largest influencing density, times
// σ_t along the ray.
#pragma once

#include <optional>

#include "illum/medium/medium.h"
#include "illum/medium/medium_box.h"
#include "illum/medium/medium_spectrum.h"
#include "illum/medium/sampled_grid.h"
#include "illum/radiometry/emission.h"

namespace illum {

struct UniformGridParams {
    MediumBox box;
    MediumSpectrum sigma_a, sigma_s; // already times "scale"
    float g = 0;
    SampledGrid<float> density;
    std::optional<SampledGrid<float>> temperature;
    float temperature_offset = 0, temperature_scale = 1;
    Emission le{Color3(0.0f)};
    bool le_nonzero = false;
    SampledGrid<float> le_scale; // 1x1x1 holding 1 when "Lescale" is absent
};

class UniformGridMedium final : public Medium {
public:
    explicit UniformGridMedium(UniformGridParams p);

    bool is_emissive() const override { return emissive_; }
    MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const override;
    MajorantIterator sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const override;

    const MajorantGrid& majorant_grid() const { return majorant_; }
    std::size_t bytes() const;

private:
    UniformGridParams p_;
    bool emissive_;
    MajorantGrid majorant_;
};

} // namespace illum

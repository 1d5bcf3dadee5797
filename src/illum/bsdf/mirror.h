// A perfect mirror: all light leaves in the mirror direction, scaled by a reflectance R (1 is lossless).
// A delta lobe: f() and pdf() are 0; sample() returns wi = (-wo.x, -wo.y, wo.z), pdf 1, f = R / |cos θi|.
#pragma once

#include "illum/bsdf/common.h"

namespace illum {

class MirrorBxDF final : public BxDF {
public:
    explicit MirrorBxDF(SampledSpectrum reflectance = SampledSpectrum(1)) : reflectance_(reflectance) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(reflectance, 0, 1), "mirror",
                      "reflectance must be in [0, 1], got " + str(reflectance));
    }
    std::uint8_t flags() const override { return kSpecularReflection; }
    bool isotropic() const override { return true; }
    Bsdf3 f(Vector3f, Vector3f, TransportMode) const override { return {}; }
    SolidAnglePdf pdf(Vector3f, Vector3f, TransportMode) const override { return SolidAnglePdf(0); }
    bool reads_lobe_sample() const override { return false; }
    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f, TransportMode) const override {
        Vector3f wi = reflect_z(wo);
        if (wi.z == 0) return std::nullopt;
        return BSDFSample{wi, Bsdf3(reflectance_ / std::abs(wi.z)), SolidAnglePdf(1), kSpecularReflection};
    }

private:
    SampledSpectrum reflectance_;
};

} // namespace illum

// Toon (cel) shading, NON-PHYSICAL: the diffuse term is quantised into bands and the highlight is a hard
// disc. The lit fraction cos θi is rounded up to one of `bands` levels and the highlight adds ks
// wherever the half vector lies within `highlight` degrees of the normal:
//   f = ρ/π · ceil(bands · cos θi)/(bands · cos θi) + ks/π · [θh <= highlight] / cos θi
// (the 1/cos θi makes the reflected radiance f cos θi piecewise constant: flat bands). It is neither
// reciprocal nor energy conserving; the audits report those checks without requiring them. Sampled
// uniformly over the hemisphere (f cos θi is bounded, so the weights are too).
#pragma once

#include "illum/bsdf/common.h"
#include "illum/math/warp.h"

namespace illum {

class ToonBxDF final : public BxDF {
public:
    ToonBxDF(SampledSpectrum reflectance, SampledSpectrum ks, int bands, float highlight_degrees)
        : rho_(reflectance), ks_(ks), bands_(float(bands)) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(reflectance, 0, 1), "toon",
                      "reflectance must be in [0, 1], got " + str(reflectance));
        ILLUM_REQUIRE(in_range(ks, 0, 1), "toon", "ks must be in [0, 1], got " + str(ks));
        ILLUM_REQUIRE(bands >= 1 && bands <= 64, "toon",
                      "bands must be in [1, 64], got " + std::to_string(bands));
        ILLUM_REQUIRE(in_range(highlight_degrees, 0, 90), "toon",
                      "highlight must be in [0, 90] degrees, got " + str(highlight_degrees));
        cos_highlight_ = std::cos(highlight_degrees * kPi / 180);
    }
    std::uint8_t flags() const override { return kDiffuseReflection; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        float c = std::abs(wi.z);
        if (c < 1e-6f) return {};
        float lit = std::min(1.0f, std::ceil(bands_ * c) / bands_);
        SampledSpectrum v = rho_ * (kInvPi * lit / c);
        Vector3f h = wo + wi;
        if (length_squared(h) > 0 && std::abs(normalize(h).z) >= cos_highlight_) v += ks_ * (kInvPi / c);
        return Bsdf3(v);
    }
    bool reads_lobe_sample() const override { return false; }
    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f u, TransportMode mode) const override {
        Vector3f wi = sample_uniform_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        if (wi.z == 0) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(uniform_hemisphere_pdf()), kDiffuseReflection};
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        return SolidAnglePdf(uniform_hemisphere_pdf());
    }

private:
    SampledSpectrum rho_, ks_;
    float bands_ = 3, cos_highlight_ = 1;
};

} // namespace illum

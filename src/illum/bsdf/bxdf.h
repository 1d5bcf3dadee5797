// The BSDF interface (DESIGN.md §3). All directions are in the local shading frame: the normal is +z,
// wo (towards the viewer) and wi (towards the light) both point away from the surface.
//
// f(wo, wi) is the BSDF value [sr^-1] without the cosine. sample() returns a direction with the value
// and the solid-angle pdf; f·|cos θi|/pdf is the path throughput weight. Delta (specular) lobes never
// come out of f() or pdf(): sample() returns them with the Specular flag, a pdf equal to the
// probability of choosing the lobe and f = (lobe's weight)·pdf/|cos θi|.
#pragma once

#include <cstdint>
#include <optional>

#include "illum/math/frame.h"
#include "illum/math/vector.h"
#include "illum/radiometry/quantity.h"

namespace illum {

// Radiance: the path carries radiance from lights to the camera (camera paths).
// Importance: the path carries importance from the camera to lights (light paths, photons).
// They differ where refraction makes the BSDF non-symmetric (the 1/η² radiance scaling).
enum class TransportMode : std::uint8_t { Radiance, Importance };

enum BxDFFlags : std::uint8_t {
    kNone = 0,
    kReflection = 1 << 0,
    kTransmission = 1 << 1,
    kDiffuse = 1 << 2,
    kGlossy = 1 << 3,
    kSpecular = 1 << 4,
    kDiffuseReflection = kDiffuse | kReflection,
    kDiffuseTransmission = kDiffuse | kTransmission,
    kGlossyReflection = kGlossy | kReflection,
    kGlossyTransmission = kGlossy | kTransmission,
    kSpecularReflection = kSpecular | kReflection,
    kSpecularTransmission = kSpecular | kTransmission,
    kAll = kDiffuse | kGlossy | kSpecular | kReflection | kTransmission,
};
constexpr BxDFFlags operator|(BxDFFlags a, BxDFFlags b) {
    return BxDFFlags(std::uint8_t(a) | std::uint8_t(b));
}
constexpr bool has_flag(std::uint8_t flags, BxDFFlags f) { return (flags & f) != 0; }

// The lobes a restricted sample or pdf may use (pbrt-v4's BxDFReflTransFlags): a layered model samples
// "transmission only" to enter or leave through its coat and "reflection only" to stay inside it. The
// restricted density is the full one conditioned on the chosen side.
enum class Lobes : std::uint8_t { All, Reflection, Transmission };

struct BSDFSample {
    Vector3f wi;
    Bsdf3 f;
    SolidAnglePdf pdf;
    std::uint8_t flags = kNone;
    float eta = 1; // relative index of refraction along wi for transmission, 1 otherwise
    // True when pdf is only proportional to the true density (stochastic layered models); MIS must then
    // not use it against other strategies.
    bool pdf_is_proportional = false;

    bool is_specular() const { return has_flag(flags, kSpecular); }
    bool is_transmission() const { return has_flag(flags, kTransmission); }
    bool is_reflection() const { return has_flag(flags, kReflection); }
    // The path throughput weight f |cos θi| / pdf (dimensionless), for a sample in the local shading
    // frame only (BxDF::sample); BSDF::sample returns wi in world space.
    SampledSpectrum weight() const { return throughput_weight(f, std::abs(wi.z), pdf); }
};

// The value and both densities of one pair of directions, as a bidirectional connection needs them at
// each of its ends (Veach 1997 eq. 10.9): f(wo, wi), and where has_pdfs the density of sampling wi from wo
// and that of sampling wo from wi (both in radiance mode, as BSDF::pdf's default).
struct BSDFEval {
    Bsdf3 f;
    float pdf_wi = 0; // pdf(wo → wi) [sr^-1]
    float pdf_wo = 0; // pdf(wi → wo) [sr^-1]
    bool has_pdfs = false;
};

class BxDF {
public:
    virtual ~BxDF() = default;
    virtual std::uint8_t flags() const = 0;
    virtual Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const = 0;
    // uc picks a lobe, u picks a direction in it. Returns nothing when no direction is sampled.
    virtual std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const = 0;
    // Whether sample() reads uc. A model with one lobe does not, and its caller may then leave the sampler's
    // dimension for uc uncomputed (Sampler::get_1d_if). The audit checks that such a model's samples do not
    // depend on uc.
    virtual bool reads_lobe_sample() const { return true; }
    // Whether f() and pdf() are unchanged when wo and wi turn together about the normal, and sample() turns
    // with wo (its directions' distribution does). Such a model may be placed in any frame around the shading
    // normal: the materials then build one from the normal alone (placed() in bsdf/material.h: no square
    // root, no tangent). The audit checks the claim.
    virtual bool isotropic() const { return false; }
    virtual SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const = 0;
    // f (wo.z and wi.z nonzero) and, in a model that computes them with f at little extra cost, the two
    // densities (has_pdfs): the values f() and pdf() give. By default f alone: a caller that needs the
    // densities asks pdf() for them only when it does (a blocked connection does not), which matters
    // where they are costly (the stochastic layered models).
    virtual BSDFEval eval(Vector3f wo, Vector3f wi, TransportMode mode) const { return {f(wo, wi, mode)}; }
};

// A BxDF placed in the world by a shading frame.
class BSDF {
public:
    BSDF() = default;
    BSDF(const BxDF* bxdf, const Frame& frame) : bxdf_(bxdf), frame_(frame) {}

    explicit operator bool() const { return bxdf_ != nullptr; }
    const BxDF* bxdf() const { return bxdf_; }
    const Frame& frame() const { return frame_; }
    bool reads_lobe_sample() const { return bxdf_->reads_lobe_sample(); }
    std::uint8_t flags() const { return bxdf_->flags(); }
    bool is_non_specular() const { return (flags() & (kDiffuse | kGlossy)) != 0; }

    Vector3f to_local(Vector3f v) const { return frame_.to_local(v); }
    Vector3f to_world(Vector3f v) const { return frame_.to_world(v); }

    Bsdf3 f(Vector3f wo_world, Vector3f wi_world, TransportMode mode = TransportMode::Radiance) const {
        Vector3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return {};
        return bxdf_->f(wo, wi, mode);
    }
    SolidAnglePdf pdf(Vector3f wo_world, Vector3f wi_world,
                      TransportMode mode = TransportMode::Radiance) const {
        Vector3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return {};
        return bxdf_->pdf(wo, wi, mode);
    }
    // f(wo, wi) in `mode` and, where the model gives them (BxDF::eval), pdf(wo, wi) and pdf(wi, wo): what
    // f() and the two pdf() calls return, with the directions taken into the shading frame once.
    BSDFEval eval(Vector3f wo_world, Vector3f wi_world, TransportMode mode) const {
        Vector3f wo = to_local(wo_world), wi = to_local(wi_world);
        if (wo.z == 0) return {};
        if (wi.z == 0) return {bxdf_->f(wo, wi, mode)};
        return bxdf_->eval(wo, wi, mode);
    }
    std::optional<BSDFSample> sample(Vector3f wo_world, float uc, Point2f u,
                                     TransportMode mode = TransportMode::Radiance) const {
        // One named result, returned on every path (so the caller's storage is the model's return slot),
        // and built there: a copy of it right after the call would stall (util/in_place.h).
        Vector3f wo = to_local(wo_world);
        std::optional<BSDFSample> s =
            wo.z == 0 ? std::optional<BSDFSample>() : bxdf_->sample(wo, uc, u, mode);
        if (s && (s->f.is_black() || !(s->pdf.value > 0) || s->wi.z == 0)) s.reset();
        if (s) s->wi = to_world(s->wi);
        return s;
    }

private:
    const BxDF* bxdf_ = nullptr;
    Frame frame_;
};

} // namespace illum

// `illum verify`'s checks (analysis/verify.h): they pass on this build, and they fail on deliberately
// broken parts handed to them: a Lambertian BSDF whose f lacks the 1/π (its albedo is π ρ), and lights
// whose photons or power() carry the wrong power. A check that cannot fail proves nothing.
#include <gtest/gtest.h>

#include "illum/analysis/bsdf_checks.h"
#include "illum/analysis/light_checks.h"
#include "illum/analysis/radiometry_checks.h"
#include "illum/analysis/verify.h"
#include "illum/bsdf/lambert.h"
#include "illum/light/point_light.h"
#include "illum/math/warp.h"
#include "illum/util/error.h"

namespace illum {
namespace {

// Lambert with f = ρ instead of ρ/π: the bug the checks must catch. Sampling is cosine-weighted, as the
// real one's, so the path weight f cos/pdf is π ρ.
class LambertWithoutInvPi final : public BxDF {
public:
    explicit LambertWithoutInvPi(SampledSpectrum r) : r_(r) {}
    std::uint8_t flags() const override { return kDiffuseReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        return same_hemisphere(wo, wi) ? Bsdf3(r_) : Bsdf3();
    }
    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f u, TransportMode mode) const override {
        Vector3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        float pdf = cosine_hemisphere_pdf(std::abs(wi.z));
        if (!(pdf > 0)) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(pdf), kDiffuseReflection};
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        return SolidAnglePdf(same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.0f);
    }

private:
    SampledSpectrum r_;
};

const BxDF* broken_lambert(SampledSpectrum r, ScratchArena& arena) {
    return arena.make<LambertWithoutInvPi>(r);
}

VerifyOptions options() {
    VerifyOptions o;
    o.threads = 2;
    return o;
}

TEST(Verify, BrokenLambertFailsTheEnergyAudit) {
    AuditTraits t;
    EXPECT_TRUE(check_bxdf_energy(LambertBxDF(SampledSpectrum(0.5f)), "lambert", t, options()).passed);
    VerifyCheck broken =
        check_bxdf_energy(LambertWithoutInvPi(SampledSpectrum(0.5f)), "broken", t, options());
    EXPECT_FALSE(broken.passed);
    EXPECT_NEAR(broken.measured, kPiD * 0.5, 0.01) << "its albedo is π ρ";
    EXPECT_TRUE(
        check_bxdf_reciprocity(LambertWithoutInvPi(SampledSpectrum(0.5f)), "broken", t, options()).passed)
        << "it is still reciprocal: only the energy audit sees this bug";
}

TEST(Verify, BrokenLambertFailsTheLambertianPlane) {
    EXPECT_TRUE(check_lambertian_plane(0.6, options()).passed);
    VerifyCheck broken = check_lambertian_plane(0.6, options(), broken_lambert);
    EXPECT_FALSE(broken.passed) << broken.measured;
    EXPECT_NEAR(broken.measured / broken.expected, kPiD, 0.05);
}

TEST(Verify, BrokenLambertFailsTheClosedFurnace) {
    // ρ = 0.25 keeps the broken one's π ρ = 0.79 below 1, so its furnace converges, to the wrong value.
    EXPECT_TRUE(check_closed_furnace(0.25, 0.7, options()).passed);
    VerifyCheck broken = check_closed_furnace(0.25, 0.7, options(), broken_lambert);
    EXPECT_FALSE(broken.passed);
    EXPECT_NEAR(broken.measured, 0.7 / (1 - kPiD * 0.25), 0.05 * broken.measured) << "Le/(1 - π ρ)";
}

// A point light that forwards everything to a real one, for the broken variants below to change one thing.
class ForwardingPointLight : public Light {
public:
    explicit ForwardingPointLight(Intensity3 i) : Light(LightType::DeltaPosition), real_({0, 0, 0}, i) {}
    std::optional<LightLiSample> sample_li(const LightSampleContext& c, Point2f u,
                                           const SampledWavelengths& l) const override {
        return real_.sample_li(c, u, l);
    }
    SolidAnglePdf pdf_li(const LightSampleContext& c, Vector3f w, const SurfaceHit* h) const override {
        return real_.pdf_li(c, w, h);
    }
    Power3 power() const override { return real_.power(); }
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& l) const override {
        return real_.sample_le(u1, u2, l);
    }
    void pdf_le(const Ray& r, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override {
        real_.pdf_le(r, n, pos, dir);
    }

protected:
    PointLight real_;
};

// One whose photons carry half their power (a pdf_dir of 1/(2π), a hemisphere's, with photons over the
// whole sphere), and one whose power() forgets the 4π.
class HalfFluxPointLight final : public ForwardingPointLight {
public:
    using ForwardingPointLight::ForwardingPointLight;
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& l) const override {
        auto s = real_.sample_le(u1, u2, l);
        if (s) s->flux = s->flux * 0.5f;
        return s;
    }
};

class PowerWithout4PiPointLight final : public ForwardingPointLight {
public:
    using ForwardingPointLight::ForwardingPointLight;
    Power3 power() const override { return real_.power() * (1 / (4 * kPi)); }
};

TEST(Verify, BrokenLightPowerFails) {
    Intensity3 I(0.5f, 1, 2);
    Color3 phi = I.rgb() * float(4 * kPiD);
    PointLight good({0, 0, 0}, I);
    EXPECT_TRUE(check_light_power(good, "point", "Φ = 4π I", phi, 10000, options()).passed);
    EXPECT_TRUE(check_light_power_method(good, "point", "Φ = 4π I", phi, options()).passed);
    HalfFluxPointLight half(I);
    EXPECT_FALSE(check_light_power(half, "half-flux point", "Φ = 4π I", phi, 10000, options()).passed);
    EXPECT_TRUE(check_light_power_method(half, "half-flux point", "Φ = 4π I", phi, options()).passed);
    PowerWithout4PiPointLight no4pi(I);
    EXPECT_TRUE(check_light_power(no4pi, "point", "Φ = 4π I", phi, 10000, options()).passed);
    EXPECT_FALSE(check_light_power_method(no4pi, "point", "Φ = 4π I", phi, options()).passed);
}

// Every check but the BSDF audits (the CLI test runs those through `illum verify --json`) passes.
TEST(Verify, RadiometryLightsAndEnvmapPass) {
    VerifyReport r = run_verify(options(), {"radiometry", "lights", "envmap"});
    EXPECT_GE(r.checks.size(), 35u);
    for (const VerifyCheck& c : r.checks) EXPECT_TRUE(c.passed) << verify_line(c);
    EXPECT_THROW(run_verify(options(), {"nonsense"}), Error);
}

TEST(Verify, ToleranceRule) {
    VerifyOptions o;
    VerifyCheck c = judge("g", "n", "x = 1", 1.0, {1.03, 0.01}, 0.0, o);
    EXPECT_NEAR(c.tolerance, 0.04, 1e-12);
    EXPECT_TRUE(c.passed);
    EXPECT_FALSE(judge("g", "n", "x = 1", 1.0, {1.05, 0.01}, 0.0, o).passed);
    EXPECT_FALSE(judge("g", "n", "x = 1", 1.0, {std::nan(""), 0.01}, 0.0, o).passed);
    EXPECT_TRUE(judge("g", "n", "x = 1", 1.0, {1.0005, 0.0}, 1e-3, o).passed);
    // Too noisy to decide (a diverging estimate's σ covers anything), or non-finite samples dropped.
    EXPECT_FALSE(judge("g", "n", "x = 1", 1.0, {1e20, 1e20}, 0.0, o).passed);
    EXPECT_FALSE(judge("g", "n", "x = 1", 1.0, {1.0, 0.02}, 0.0, o).passed);
    EXPECT_FALSE(judge("g", "n", "x = 1", 1.0, {1.0, 0.001, 3}, 0.0, o).passed);
}

} // namespace
} // namespace illum

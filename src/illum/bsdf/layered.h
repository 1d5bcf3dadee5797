// A coated (layered) BSDF: a dielectric coat (smooth or rough) at height z = thickness over a
// reflection-only base at z = 0, with an optional homogeneous medium between them (extinction 1 per unit
// of `thickness`, single-scattering `albedo`, Henyey-Greenstein phase function `g`). Light may bounce
// between the interfaces and scatter in the medium any number of times. The model is pbrt-v4's coated
// materials (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., §14.3), i.e. the
// position-free Monte Carlo of Guo, Hašan, Zhao 2018, "Position-Free Monte Carlo Simulation for Arbitrary
// Layered BSDFs"; written from those descriptions. Two-sided: the coat is on both faces.
//
// f(wo, wi) is an unbiased estimate, averaged over `samples` random walks: each walk refracts wo into the
// layer (transmission-only sample of the coat) and gets an exit direction by refracting wi in (adjoint
// mode). Through the layer (no medium) the walk's weight drops by the transmittance
// Tr = exp(-thickness / |cos θ|); with a medium the free path is sampled (exponential in depth) and a
// scattering event samples the phase function. At every base or medium event the walk adds the
// next-event estimate through the exit direction; at the coat (from below) it continues by internal
// reflection (reflection-only sample). With a rough coat the exit through the coat is also reached by the
// walk's own directions, and the two estimates are combined by the power heuristic. illum weighs both
// with the densities of the same inner direction (pbrt-v4 uses the reverse-direction density of the coat
// for the second, which makes the two weights not quite sum to one). Russian roulette after 3 events
// (see kRouletteWeight).
// The walk's random numbers come from a generator seeded by the directions, so f is a function.
//
// sample(): the same walk from wo, multiplying the value and density of each event, until it leaves
// through the coat; pdf_is_proportional (the product is not the marginal density, the ratio is right).
// pdf(): an approximation for MIS weights only (as pbrt-v4's): the coat's reflection density plus the
// probability of entering times an estimate of the base's density seen through the coat, mixed with a
// uniform density (10%) so that it is never zero where f is not.
#pragma once

#include <cstring>
#include <limits>

#include "illum/bsdf/common.h"
#include "illum/bsdf/layer_interfaces.h"
#include "illum/medium/henyey_greenstein.h"

namespace illum {

namespace bsdf_detail {
// SplitMix64 (Steele, Lea, Flood 2014): a tiny deterministic generator for the layered walk.
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    float uniform() { return float(next() >> 40) * 0x1p-24f; } // [0, 1)
    Point2f uniform2() {
        float a = uniform();
        return {a, uniform()};
    }
};
// model.sample(w, uc, u, rest...) with uc drawn before u. (As two arguments of the call, the order of the
// draws was the compiler's: g++ and clang++ evaluate arguments in opposite orders, and so rendered different
// images of the same layered scene.)
template <class Model, class... Rest>
auto sample_event(const Model& model, Vector3f w, SplitMix64& rng, Rest... rest) {
    const float uc = rng.uniform();
    const Point2f u = rng.uniform2();
    return model.sample(w, uc, u, rest...);
}
inline std::uint64_t hash_floats(std::initializer_list<float> v) {
    std::uint64_t h = 0x243F6A8885A308D3ull;
    for (float x : v) {
        std::uint32_t bits;
        std::memcpy(&bits, &x, 4);
        h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h = SplitMix64{h}.next();
    }
    return h;
}
inline TransportMode adjoint(TransportMode m) {
    return m == TransportMode::Radiance ? TransportMode::Importance : TransportMode::Radiance;
}
// Transmittance over a depth difference dz along w, extinction 1 per unit depth.
inline float layer_transmittance(float dz, Vector3f w) {
    if (std::abs(dz) <= 1e-30f) return 1;
    return std::exp(-std::abs(dz / w.z));
}
inline bool usable(const std::optional<BSDFSample>& s) {
    return s && !s->f.is_black() && s->pdf > SolidAnglePdf(0) && s->wi.z != 0;
}
} // namespace bsdf_detail

// The layer between coat and base.
struct LayerMedium {
    float thickness = 0.01f;
    SampledSpectrum albedo{0.0f};
    float g = 0;
};

template <class Base>
class LayeredBxDF final : public BxDF {
public:
    LayeredBxDF(DielectricInterface coat, Base base, LayerMedium medium, int max_depth, int samples,
                const char* name = "coated")
        : coat_(coat), base_(base), medium_(medium), max_depth_(max_depth), samples_(samples) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(medium.thickness, 0, 1e6f), name,
                      "thickness must be >= 0, got " + str(medium.thickness));
        ILLUM_REQUIRE(in_range(medium.albedo, 0, 1), name,
                      "albedo must be in [0, 1], got " + str(medium.albedo));
        ILLUM_REQUIRE(in_range(medium.g, -0.999f, 0.999f), name,
                      "g must be in (-1, 1), got " + str(medium.g));
        ILLUM_REQUIRE(max_depth >= 1 && max_depth <= 1000, name,
                      "max_depth must be in [1, 1000], got " + std::to_string(max_depth));
        ILLUM_REQUIRE(samples >= 1 && samples <= 1000, name,
                      "samples must be in [1, 1000], got " + std::to_string(samples));
        // The walk tells the interfaces apart by depth, so the layer is never quite flat.
        medium_.thickness = std::max(medium.thickness, std::numeric_limits<float>::min());
        has_medium_ = !medium.albedo.is_black() && medium.thickness > 0;
        base_specular_ = !has_flag(base_.flags(), BxDFFlags(kDiffuse | kGlossy));
    }

    std::uint8_t flags() const override {
        std::uint8_t f = kReflection;
        if (coat_.is_specular()) f |= kSpecular;
        if (has_flag(base_.flags(), kDiffuse) || has_medium_) return f | kDiffuse;
        if (!coat_.is_specular() || has_flag(base_.flags(), kGlossy)) f |= kGlossy;
        return f;
    }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        using namespace bsdf_detail;
        if (!same_hemisphere(wo, wi) || wo.z == 0) return {};
        if (wo.z < 0) {
            wo = -wo;
            wi = -wi;
        }
        const float h = medium_.thickness;
        const bool coat_specular = coat_.is_specular();
        SplitMix64 rng{hash_floats({wo.x, wo.y, wo.z, wi.x, wi.y, wi.z})};
        auto r = [&] { return rng.uniform(); };
        auto r2 = [&] { return rng.uniform2(); };
        // The coat's own reflection (zero for a smooth coat: a delta).
        Bsdf3 sum = coat_.f(wo, wi, mode) * float(samples_);
        for (int s = 0; s < samples_; ++s) {
            auto wos = sample_event(coat_, wo, rng, mode, Lobes::Transmission);
            if (!usable(wos)) continue;
            auto wis = sample_event(coat_, wi, rng, adjoint(mode), Lobes::Transmission);
            if (!usable(wis)) continue;
            SampledSpectrum beta = wos->weight();
            SampledSpectrum exit_weight = wis->f / wis->pdf; // without the cosine, which the event gives
            Vector3f exit_dir = -wis->wi; // the inner direction of travel that leaves along wi
            Vector3f w = wos->wi;         // direction of travel, down into the layer
            float z = h;
            for (int depth = 0; depth < max_depth_; ++depth) {
                if (depth > 3 && beta.max_component() < kRouletteWeight) {
                    float survive = beta.max_component() / kRouletteWeight;
                    if (!(r() < survive)) break;
                    beta /= survive;
                }
                if (!has_medium_) {
                    z = z == h ? 0 : h;
                    beta *= layer_transmittance(h, w);
                } else {
                    float zp = next_depth(z, w, r());
                    if (zp == z) continue;
                    if (zp > 0 && zp < h) {
                        // Scattering in the medium: next-event estimate through the exit direction.
                        SolidAnglePdf p_exit(medium_phase().p(dot(w, exit_dir))); // a phase function: a pdf
                        float wt = coat_specular ? 1 : power_heuristic(wis->pdf, p_exit);
                        sum += beta * medium_.albedo * exit_weight *
                               (p_exit * wt * layer_transmittance(zp - h, exit_dir));
                        float pdf_phase;
                        Vector3f wn = medium_phase().sample(w, r2(), &pdf_phase);
                        if (!(pdf_phase > 0) || wn.z == 0) continue;
                        beta *= medium_.albedo; // p / pdf = 1
                        w = wn;
                        z = zp;
                        if (!coat_specular && w.z > 0)
                            sum += through_rough_coat(beta, w, wi, SolidAnglePdf(pdf_phase), mode) *
                                   layer_transmittance(zp - h, w);
                        continue;
                    }
                    z = std::clamp(zp, 0.0f, h);
                }
                if (z == h) {
                    // At the coat from below: internal reflection continues the walk (transmission is
                    // counted by the next-event estimates).
                    auto rs = sample_event(coat_, -w, rng, mode, Lobes::Reflection);
                    if (!usable(rs)) break;
                    beta *= rs->weight();
                    w = rs->wi;
                    continue;
                }
                // At the base.
                if (!base_specular_) {
                    Bsdf3 fb = base_.f(-w, exit_dir, mode);
                    if (!fb.is_black()) {
                        float wt =
                            coat_specular ? 1 : power_heuristic(wis->pdf, base_.pdf(-w, exit_dir, mode));
                        sum += beta * fb * exit_weight *
                               (std::abs(exit_dir.z) * wt * layer_transmittance(h, exit_dir));
                    }
                }
                auto bs = sample_event(base_, -w, rng, mode);
                if (!usable(bs) || bs->wi.z <= 0) break;
                beta *= bs->weight();
                w = bs->wi;
                if (!coat_specular)
                    sum +=
                        through_rough_coat(beta, w, wi, base_specular_ ? SolidAnglePdf(0) : bs->pdf, mode) *
                        layer_transmittance(h, w);
            }
        }
        return sum / float(samples_);
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        using namespace bsdf_detail;
        if (wo.z == 0) return std::nullopt;
        bool flip = wo.z < 0;
        if (flip) wo = -wo;
        auto bs = coat_.sample(wo, uc, u, mode);
        if (!usable(bs)) return std::nullopt;
        if (bs->is_reflection()) {
            if (flip) bs->wi = -bs->wi;
            bs->pdf_is_proportional = true;
            return bs;
        }
        SplitMix64 rng{hash_floats({wo.x, wo.y, wo.z, uc, u.x, u.y})};
        auto r = [&] { return rng.uniform(); };
        auto r2 = [&] { return rng.uniform2(); };
        const float h = medium_.thickness;
        // The walk's products of f |cos| and of pdfs over its events: their units depend on the number of
        // events, so they are carried as numbers and only their ratio (dimensionless) is meaningful; the
        // sample returns them as a BSDF value and a pdf proportional to the true ones.
        SampledSpectrum f = bs->f.s * std::abs(bs->wi.z);
        float pdf = bs->pdf.value;
        bool specular = bs->is_specular();
        Vector3f w = bs->wi;
        float z = h;
        for (int depth = 0; depth < max_depth_; ++depth) {
            float weight = f.max_component() / pdf;
            if (depth > 3 && weight < kRouletteWeight) {
                float survive = weight / kRouletteWeight;
                if (!(r() < survive)) return std::nullopt;
                pdf *= survive;
            }
            if (w.z == 0) return std::nullopt;
            if (!has_medium_) {
                z = z == h ? 0 : h;
                f *= layer_transmittance(h, w);
            } else {
                // The free path is sampled in proportion to the transmittance, which cancels.
                float zp = next_depth(z, w, r());
                if (zp == z) return std::nullopt;
                if (zp > 0 && zp < h) {
                    float pdf_phase;
                    Vector3f wn = medium_phase().sample(w, r2(), &pdf_phase);
                    if (!(pdf_phase > 0) || wn.z == 0) return std::nullopt;
                    f *= medium_.albedo * pdf_phase; // p = pdf
                    pdf *= pdf_phase;
                    specular = false;
                    w = wn;
                    z = zp;
                    continue;
                }
                z = std::clamp(zp, 0.0f, h);
            }
            std::optional<BSDFSample> s =
                z == 0 ? sample_event(base_, -w, rng, mode) : sample_event(coat_, -w, rng, mode);
            if (!usable(s)) return std::nullopt;
            f *= s->f.s;
            pdf *= s->pdf.value;
            specular = specular && s->is_specular();
            w = s->wi;
            if (s->is_transmission()) { // left through the coat
                if (w.z <= 0) return std::nullopt;
                std::uint8_t fl = kReflection | (specular ? kSpecular : kGlossy);
                BSDFSample out{flip ? -w : w, Bsdf3(f), SolidAnglePdf(pdf), fl};
                out.pdf_is_proportional = true;
                return out;
            }
            if (z == 0 && w.z <= 0) return std::nullopt; // the base does not transmit
            f *= std::abs(w.z);
        }
        return std::nullopt;
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        using namespace bsdf_detail;
        if (!same_hemisphere(wo, wi) || wo.z == 0) return SolidAnglePdf(0);
        if (wo.z < 0) {
            wo = -wo;
            wi = -wi;
        }
        SplitMix64 rng{hash_floats({wi.x, wi.y, wi.z, wo.x, wo.y, wo.z})};
        // The coat reflects with probability about R(cos θo) (exactly, for a smooth coat); the rest enters.
        float enter = 1 - coat_.fresnel_reflectance(wo.z);
        SolidAnglePdf through(0);
        for (int s = 0; s < samples_; ++s) {
            auto wos = sample_event(coat_, wo, rng, mode, Lobes::Transmission);
            auto wis = sample_event(coat_, wi, rng, adjoint(mode), Lobes::Transmission);
            if (!usable(wos) || !usable(wis)) continue;
            Vector3f down = wos->wi, exit_dir = -wis->wi;
            if (coat_.is_specular()) {
                through += base_.pdf(-down, exit_dir, mode);
                continue;
            }
            // Two estimates of the density of the base's direction through a rough coat, by MIS.
            auto bs = sample_event(base_, -down, rng, mode);
            if (!usable(bs)) continue;
            if (base_specular_) {
                through += coat_.pdf(-bs->wi, wi, mode);
            } else {
                SolidAnglePdf p_base = base_.pdf(-down, exit_dir, mode);
                through += power_heuristic(wis->pdf, p_base) * p_base;
                SolidAnglePdf p_coat = coat_.pdf(-bs->wi, wi, mode);
                through += power_heuristic(bs->pdf, p_coat) * p_coat;
            }
        }
        SolidAnglePdf p = coat_.pdf(wo, wi, mode) + enter * through / float(samples_);
        // A tenth of the density is uniform over the sphere, as pbrt-v4 does.
        return 0.9f * p + SolidAnglePdf(0.1f / (4 * kPi));
    }

private:
    // Russian roulette after 3 events lifts a walk whose weight fell below this back up to it (survival
    // probability weight / kRouletteWeight). pbrt-v4 lifts it to 1 instead, which makes the estimate of
    // f heavy-tailed (rare walks 100x their neighbours); lifting to 0.25 costs a few more events.
    static constexpr float kRouletteWeight = 0.25f;

    HenyeyGreenstein medium_phase() const { return HenyeyGreenstein{medium_.g}; }

    // The depth reached along w from z by a free path sampled with density exp(-s) in optical depth
    // (extinction 1): dz = -ln(1 - u) |cos θ|.
    float next_depth(float z, Vector3f w, float u) const {
        float dz = -std::log1p(-u) * std::abs(w.z);
        return w.z > 0 ? z + dz : z - dz;
    }

    // The contribution of leaving a rough coat along wi, reached by the walk's own direction w (travel,
    // upwards) that was sampled with density pdf_w (0: a delta, no MIS): beta f_coat(-w, wi) weighed
    // against the next-event estimate, whose density for the same inner direction is that of refracting
    // wi inwards (adjoint mode).
    Bsdf3 through_rough_coat(SampledSpectrum beta, Vector3f w, Vector3f wi, SolidAnglePdf pdf_w,
                             TransportMode mode) const {
        using namespace bsdf_detail;
        Bsdf3 fc = coat_.f(-w, wi, mode);
        if (fc.is_black()) return Bsdf3();
        float wt = 1;
        if (pdf_w > SolidAnglePdf(0))
            wt = power_heuristic(pdf_w, coat_.pdf(wi, -w, adjoint(mode), Lobes::Transmission));
        return beta * fc * wt;
    }

    DielectricInterface coat_;
    Base base_;
    LayerMedium medium_;
    int max_depth_, samples_;
    bool has_medium_ = false, base_specular_ = false;
};

} // namespace illum

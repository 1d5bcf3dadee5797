// Layered materials: a smooth dielectric coat (index η) over a base (Lambertian for coated-diffuse, a
// rough conductor for coated-conductor), with no medium between them. Light refracts into the coat,
// bounces between base and coat any number of times and leaves; the result is evaluated stochastically
// by a random walk between the two interfaces, which is the reference behaviour of pbrt-v4's coated
// materials (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., §14.3; the walk is the
// position-free Monte Carlo of Guo, Hašan, Zhao 2018, "Position-Free Monte Carlo Simulation for
// Arbitrary Layered BSDFs"). Written from that description:
//
// f(wo, wi): average over `samples` walks. Each walk refracts wo into the coat (sampled transmission of
//   the top, mode), and refracts wi in (sampled transmission, adjoint mode) to give the exit direction;
//   at the base it adds the next-event estimate  β f_base(-w, -w_exit) |cos| T_exit  and continues by
//   sampling the base; at the coat (from below) it continues on internal reflection and ends on
//   transmission (that path's exit was already counted). Russian roulette after 3 bounces. The random
//   numbers come from a generator seeded by a hash of (wo, wi), so f is a deterministic function.
// sample(): the same walk from wo, multiplying f and pdf of each event; it returns when the walk leaves
//   through the coat, with pdf_is_proportional = true (the product is not the marginal density).
// pdf(): an approximation (pdf_is_proportional): the mix of the coat's specular reflection (a delta,
//   absent from pdf) and a cosine lobe; fine for MIS heuristics, not an exact density.
// Energy: the walk conserves energy exactly except for walks cut at max_depth, so with a white base the
// albedo is just below 1. Mode matters only inside the layer; both exits are on the same side.
#pragma once

#include <cstring>

#include "illum/bsdf/common.h"
#include "illum/bsdf/dielectric.h"
#include "illum/bsdf/lambert.h"
#include "illum/bsdf/rough_conductor.h"
#include "illum/math/warp.h"

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
};
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
} // namespace bsdf_detail

template <class Base>
class CoatedBxDF final : public BxDF {
public:
    CoatedBxDF(float eta, Base base, int max_depth, int samples, const char* name = "coated")
        : top_(eta), base_(base), max_depth_(max_depth), samples_(samples) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(eta, 1e-3f, 100), name, "eta must be in (0, 100], got " + str(eta));
        ILLUM_REQUIRE(max_depth >= 1 && max_depth <= 1000, name,
                      "max_depth must be in [1, 1000], got " + std::to_string(max_depth));
        ILLUM_REQUIRE(samples >= 1 && samples <= 1000, name,
                      "samples must be in [1, 1000], got " + std::to_string(samples));
    }
    std::uint8_t flags() const override {
        std::uint8_t f = kReflection | kSpecular;
        return f | (has_flag(base_.flags(), kDiffuse) ? kDiffuse : kGlossy);
    }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        using namespace bsdf_detail;
        if (!same_hemisphere(wo, wi) || wo.z == 0) return {};
        if (wo.z < 0) { // two-sided: the coat is on both faces
            wo = -wo;
            wi = -wi;
        }
        SplitMix64 rng{hash_floats({wo.x, wo.y, wo.z, wi.x, wi.y, wi.z})};
        auto r = [&] { return rng.uniform(); };
        Color3 sum;
        for (int s = 0; s < samples_; ++s) {
            auto wos = sample_transmission(wo, mode);
            if (!wos) continue;
            auto wis = sample_transmission(wi, adjoint(mode));
            if (!wis) continue;
            Color3 beta = wos->f.rgb * (std::abs(wos->wi.z) / wos->pdf.value);
            Color3 exit_weight = wis->f.rgb * (std::abs(wis->wi.z) / wis->pdf.value);
            Vector3f w = wos->wi; // pointing down, into the layer
            // depth counts interface events as sample() does: a base and a coat event per iteration.
            for (int depth = 0; depth < max_depth_; depth += 2) {
                if (depth > 3 && beta.max_component() < 0.25f) {
                    float q = std::max(0.0f, 1 - beta.max_component());
                    if (r() < q) break;
                    beta /= 1 - q;
                }
                // At the base: next-event estimate through the exit direction, then scatter.
                sum += beta * base_.f(-w, -wis->wi, mode).rgb * exit_weight;
                auto bs = base_.sample(-w, r(), {r(), r()}, mode);
                if (!bs || bs->wi.z <= 0) break;
                beta *= bs->f.rgb * (std::abs(bs->wi.z) / bs->pdf.value);
                w = bs->wi; // pointing up
                // At the coat from below: internal reflection continues the walk, transmission ends it.
                auto ts = top_.sample(-w, r(), {r(), r()}, mode);
                if (!ts || ts->is_transmission()) break;
                beta *= ts->f.rgb * (std::abs(ts->wi.z) / ts->pdf.value);
                w = ts->wi; // pointing down
            }
        }
        return Bsdf3(sum / float(samples_));
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        using namespace bsdf_detail;
        if (wo.z == 0) return std::nullopt;
        bool flip = wo.z < 0;
        if (flip) wo = -wo;
        auto bs = top_.sample(wo, uc, u, mode);
        if (!bs) return std::nullopt;
        if (bs->is_reflection()) {
            if (flip) bs->wi = -bs->wi;
            bs->pdf_is_proportional = true;
            return bs;
        }
        SplitMix64 rng{hash_floats({wo.x, wo.y, wo.z, uc, u.x, u.y})};
        auto r = [&] { return rng.uniform(); };
        Color3 f = bs->f.rgb * std::abs(bs->wi.z);
        float pdf = bs->pdf.value;
        bool specular = true;
        Vector3f w = bs->wi;
        bool at_base = true; // the next interface
        for (int depth = 0; depth < max_depth_; ++depth) {
            float rr = f.max_component() / pdf;
            if (depth > 3 && rr < 0.25f) {
                float q = std::max(0.0f, 1 - rr);
                if (r() < q) return std::nullopt;
                pdf *= 1 - q;
            }
            std::optional<BSDFSample> s =
                at_base ? base_.sample(-w, r(), {r(), r()}, mode) : top_.sample(-w, r(), {r(), r()}, mode);
            if (!s || s->f.is_black() || !(s->pdf.value > 0) || s->wi.z == 0) return std::nullopt;
            f *= s->f.rgb;
            pdf *= s->pdf.value;
            specular = specular && s->is_specular();
            w = s->wi;
            if (!at_base && s->is_transmission()) {
                if (w.z <= 0) return std::nullopt;
                std::uint8_t flags =
                    kReflection |
                    (specular ? kSpecular : (has_flag(base_.flags(), kDiffuse) ? kDiffuse : kGlossy));
                BSDFSample out{flip ? -w : w, Bsdf3(f), SolidAnglePdf(pdf), flags};
                out.pdf_is_proportional = true;
                return out;
            }
            if (at_base && w.z <= 0) return std::nullopt; // the base does not transmit
            f *= std::abs(w.z);
            at_base = !at_base;
        }
        return std::nullopt;
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        // The share of the walk that leaves diffusely: 1 - R(wo) (R goes to the delta lobe).
        float R = top_.fresnel()(std::abs(wo.z));
        return SolidAnglePdf((1 - R) * cosine_hemisphere_pdf(std::abs(wi.z)));
    }

private:
    // Transmission through the smooth coat from outside, with its weight: f |cos| / pdf = T (or T/η'²).
    std::optional<BSDFSample> sample_transmission(Vector3f w, TransportMode mode) const {
        auto s = top_.sample(w, 1.0f, {0.5f, 0.5f}, mode); // uc = 1 always refracts unless TIR
        if (!s || !s->is_transmission()) return std::nullopt;
        // Turn the lobe pick probability into certainty: pdf 1, so the weight carries T.
        s->pdf = SolidAnglePdf(1);
        return s;
    }

    DielectricBxDF top_;
    Base base_;
    int max_depth_, samples_;
};

using CoatedDiffuseBxDF = CoatedBxDF<LambertBxDF>;
using CoatedConductorBxDF = CoatedBxDF<RoughConductorBxDF>;

} // namespace illum

#include "illum/analysis/brdf_fit.h"

#include <algorithm>
#include <cmath>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include "illum/analysis/levenberg_marquardt.h"
#include "illum/bsdf/cook_torrance.h"
#include "illum/bsdf/rough_conductor.h"
#include "illum/bsdf/ward.h"

namespace illum {

namespace {

SampledSpectrum grey(double v) { return SampledSpectrum(float(v)); }

// ρd/π + ρs lobe, sampled by choosing the lobe with probability p (by the specular weights) or a
// cosine-weighted direction.
class FittedBxDF final : public BxDF {
public:
    FittedBxDF(Rgb64 rho_d, Rgb64 rho_s, std::unique_ptr<BxDF> lobe) : lobe_(std::move(lobe)) {
        for (int c = 0; c < 3; ++c) {
            rd_[c] = float(rho_d[c]);
            rs_[c] = float(rho_s[c]);
        }
        double d = rd_.average(), s = rs_.average();
        p_lobe_ = d + s > 0 ? float(std::clamp(s / (d + s), 0.05, 0.95)) : 0.5f;
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kGlossyReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        Color3 l = lobe_->f(wo, wi, mode).rgb();
        return Bsdf3(SampledSpectrum(rd_ * kInvPi + rs_ * l));
    }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        if (wo.z == 0) return std::nullopt;
        Vector3f wi;
        if (uc < p_lobe_) {
            auto s = lobe_->sample(wo, std::min(uc / p_lobe_, 0x1.fffffep-1f), u, mode);
            if (!s) return std::nullopt;
            wi = s->wi;
        } else {
            wi = sample_cosine_hemisphere(u);
            if (wo.z < 0) wi.z = -wi.z;
        }
        float pdf = this->pdf(wo, wi, mode).value;
        if (!same_hemisphere(wo, wi) || !(pdf > 0)) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(pdf), kGlossyReflection};
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        return SolidAnglePdf((1 - p_lobe_) * std::abs(wi.z) * kInvPi +
                             p_lobe_ * lobe_->pdf(wo, wi, mode).value);
    }

private:
    Color3 rd_, rs_;
    std::unique_ptr<BxDF> lobe_;
    float p_lobe_ = 0.5f;
};

struct Bounds {
    double alpha_lo, alpha_hi;
};
Bounds alpha_bounds(FitFamily f) {
    return (f == FitFamily::Ward || f == FitFamily::CookTorrance) ? Bounds{1e-3, 1} : Bounds{1e-3, 2};
}

// The lobe's values at every pair, in parallel.
void lobe_values(const BrdfSamples& s, FitFamily family, double alpha, double f0, std::vector<double>* out) {
    auto lobe = make_fit_lobe(family, alpha, f0);
    out->resize(s.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, s.size(), 4096), [&](const auto& range) {
        for (std::size_t k = range.begin(); k < range.end(); ++k)
            (*out)[k] = lobe->f(s.wo[k], s.wi[k], TransportMode::Radiance).rgb().g;
    });
}

double log_residual(double f, double model, double c) {
    return std::log1p(f * c) - std::log1p(std::max(0.0, model) * c);
}

// The start for one lobe setting: per channel, ρd and ρs >= 0 minimising Σ w (f cos - (ρd/π + ρs l) cos)²
// with w = 1 / (1 + f cos)², the first-order weight of the log metric.
void linear_start(const BrdfSamples& s, const std::vector<double>& lobe, Rgb64* rd, Rgb64* rs) {
    for (int c = 0; c < 3; ++c) {
        double saa = 0, sab = 0, sbb = 0, say = 0, sby = 0;
        for (std::size_t k = 0; k < s.size(); ++k) {
            double cs = s.wi[k].z, y = s.f[k][c] * cs, a = cs * kInvPi, b = lobe[k] * cs, w = 1 / sqr(1 + y);
            saa += w * a * a;
            sab += w * a * b;
            sbb += w * b * b;
            say += w * a * y;
            sby += w * b * y;
        }
        double det = saa * sbb - sab * sab, d = 0, sp = 0;
        if (det > 0) {
            d = (say * sbb - sby * sab) / det;
            sp = (sby * saa - say * sab) / det;
        }
        if (d < 0 || det <= 0) {
            d = 0;
            sp = sbb > 0 ? std::max(0.0, sby / sbb) : 0;
        }
        if (sp < 0) {
            sp = 0;
            d = saa > 0 ? std::max(0.0, say / saa) : 0;
        }
        (*rd)[c] = std::min(d, 10.0);
        (*rs)[c] = std::min(sp, 10.0);
    }
}

double log_cost(const BrdfSamples& s, const std::vector<double>& lobe, const Rgb64& rd, const Rgb64& rs) {
    double e = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
        for (int c = 0; c < 3; ++c)
            e += sqr(log_residual(s.f[k][c], rd[c] * kInvPi + rs[c] * lobe[k], s.wi[k].z));
    return e;
}

template <class Visit>
void for_each_bin(const FitSampling& o, Visit&& visit) {
    double max_cos = std::cos(o.max_theta_deg * kPiD / 180);
    for (int ih = 0; ih < MerlTable::kThetaH; ++ih)
        for (int id = o.theta_d_stride / 2; id < MerlTable::kThetaD; id += std::max(1, o.theta_d_stride))
            for (int ip = o.phi_d_stride / 2; ip < MerlTable::kPhiD; ip += std::max(1, o.phi_d_stride)) {
                Vector3f wo, wi;
                if (!MerlTable::bin_directions(ih, id, ip, &wo, &wi)) continue;
                if (wo.z < max_cos || wi.z < max_cos) continue;
                visit(ih, id, ip, wo, wi);
            }
}

} // namespace

std::optional<FitFamily> fit_family_from_string(const std::string& name) {
    if (name == "ggx") return FitFamily::GGX;
    if (name == "beckmann") return FitFamily::Beckmann;
    if (name == "ward") return FitFamily::Ward;
    if (name == "cook-torrance") return FitFamily::CookTorrance;
    return std::nullopt;
}

const char* to_string(FitFamily f) {
    switch (f) {
    case FitFamily::GGX:
        return "ggx";
    case FitFamily::Beckmann:
        return "beckmann";
    case FitFamily::Ward:
        return "ward";
    case FitFamily::CookTorrance:
        return "cook-torrance";
    }
    return "?";
}

std::unique_ptr<BxDF> make_fit_lobe(FitFamily family, double alpha, double f0) {
    float a = float(alpha);
    switch (family) {
    case FitFamily::GGX:
    case FitFamily::Beckmann: {
        // F = 1: Schlick's form with F0 = ((η - 1)² + k²) / ((η + 1)² + k²) = 1 - 4·10⁻⁸ at η = 1, k = 10⁴.
        Fresnel one{grey(1), grey(1e4), FresnelMode::Schlick};
        auto type = family == FitFamily::GGX ? MicrofacetType::GGX : MicrofacetType::Beckmann;
        return std::make_unique<RoughConductorBxDF>(MicrofacetDistribution(type, a, a), one);
    }
    case FitFamily::Ward:
        return std::make_unique<WardBxDF>(grey(0), grey(1), a, a);
    case FitFamily::CookTorrance: {
        // Schlick's F0 from a real index: F0 = ((η - 1)/(η + 1))², η = (1 + √F0) / (1 - √F0).
        double r = std::sqrt(std::clamp(f0, 1e-4, 0.9999));
        Fresnel f{grey((1 + r) / (1 - r)), grey(0), FresnelMode::Schlick};
        return std::make_unique<CookTorranceBxDF>(grey(0), grey(1), a, f);
    }
    }
    return nullptr;
}

std::unique_ptr<BxDF> make_fitted_bxdf(const FitParameters& p) {
    return std::make_unique<FittedBxDF>(p.rho_d, p.rho_s, make_fit_lobe(p.family, p.alpha, p.f0));
}

BrdfSamples samples_from_merl(const MerlTable& table, const FitSampling& o) {
    BrdfSamples s;
    for_each_bin(o, [&](int ih, int id, int ip, Vector3f wo, Vector3f wi) {
        Rgb64 f{table.value(ih, id, ip, 0), table.value(ih, id, ip, 1), table.value(ih, id, ip, 2)};
        if (f[0] < 0 || f[1] < 0 || f[2] < 0) return; // missing measurement
        s.wo.push_back(wo);
        s.wi.push_back(wi);
        s.f.push_back(f);
    });
    return s;
}

BrdfSamples samples_from_bxdf(const BxDF& bxdf, const FitSampling& o) {
    BrdfSamples s;
    for_each_bin(o, [&](int, int, int, Vector3f wo, Vector3f wi) {
        Color3 f = bxdf.f(wo, wi, TransportMode::Radiance).rgb();
        s.wo.push_back(wo);
        s.wi.push_back(wi);
        s.f.push_back({f.r, f.g, f.b});
    });
    return s;
}

FitError fit_error(const BrdfSamples& s, const FitParameters& p) {
    std::vector<double> lobe;
    lobe_values(s, p.family, p.alpha, p.f0, &lobe);
    double e = 0, num = 0, den = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            double cs = s.wi[k].z, model = p.rho_d[c] * kInvPi + p.rho_s[c] * lobe[k];
            e += sqr(log_residual(s.f[k][c], model, cs));
            num += sqr((s.f[k][c] - model) * cs);
            den += sqr(s.f[k][c] * cs);
        }
    FitError out;
    out.log_rms = s.size() ? std::sqrt(e / (3.0 * double(s.size()))) : 0;
    out.relative_rms = den > 0 ? std::sqrt(num / den) : 0;
    return out;
}

FitResult fit_brdf(const BrdfSamples& s, FitFamily family, int max_iterations) {
    const bool ct = family == FitFamily::CookTorrance;
    const Bounds b = alpha_bounds(family);
    // 1. The start: the best α (and F0) of a scan, ρd and ρs by weighted linear least squares.
    FitParameters best;
    best.family = family;
    double best_cost = 1e300;
    std::vector<double> lobe;
    for (double f0 : ct ? std::vector<double>{0.04, 0.5, 0.95} : std::vector<double>{1.0}) {
        for (int i = 0; i < 24; ++i) {
            double alpha = 0.005 * std::pow(b.alpha_hi / 0.005, i / 23.0);
            lobe_values(s, family, alpha, f0, &lobe);
            FitParameters p = best;
            p.alpha = alpha;
            p.f0 = f0;
            linear_start(s, lobe, &p.rho_d, &p.rho_s);
            double cost = log_cost(s, lobe, p.rho_d, p.rho_s);
            if (cost < best_cost) {
                best_cost = cost;
                best = p;
            }
        }
    }
    // 2. Levenberg-Marquardt on x = (ρd RGB, ρs RGB, ln α[, F0]). With m = ρd/π + ρs l and c = cos θi,
    // r = ln(1 + f c) - ln(1 + m c), so ∂r/∂ρd = -(c/π)/(1 + m c) and ∂r/∂ρs = -l c/(1 + m c) exactly; the
    // lobe's parameters by central differences of l, ∂r/∂q = -ρs c (∂l/∂q)/(1 + m c).
    const int n = ct ? 8 : 7;
    struct Lobes {
        double alpha = -1, f0 = -1;
        std::vector<double> values, plus, minus;
    };
    auto cache = std::make_shared<Lobes>();
    auto lobe_at = [&s, family, cache](double alpha, double f0) -> const std::vector<double>& {
        if (alpha != cache->alpha || f0 != cache->f0) {
            lobe_values(s, family, alpha, f0, &cache->values);
            cache->alpha = alpha;
            cache->f0 = f0;
        }
        return cache->values;
    };
    auto model = [](const std::vector<double>& x, int c, double l) {
        return x[std::size_t(c)] * kInvPi + x[3 + std::size_t(c)] * l;
    };
    LeastSquaresProblem prob;
    prob.residuals = [&s, ct, lobe_at, model](const std::vector<double>& x, std::vector<double>& r) {
        const std::vector<double>& l = lobe_at(std::exp(x[6]), ct ? x[7] : 1.0);
        r.resize(3 * s.size());
        for (std::size_t k = 0; k < s.size(); ++k)
            for (int c = 0; c < 3; ++c)
                r[3 * k + std::size_t(c)] = log_residual(s.f[k][c], model(x, c, l[k]), s.wi[k].z);
    };
    prob.jacobian = [&s, family, ct, n, lobe_at, model, cache](
                        const std::vector<double>& x, const std::vector<double>&, std::vector<double>& jac) {
        const double alpha = std::exp(x[6]), f0 = ct ? x[7] : 1.0;
        const std::vector<double>& l = lobe_at(alpha, f0);
        // ∂l/∂ln α and ∂l/∂F0 by central differences.
        std::vector<std::vector<double>> dl;
        const double h = 1e-4;
        lobe_values(s, family, alpha * std::exp(h), f0, &cache->plus);
        lobe_values(s, family, alpha * std::exp(-h), f0, &cache->minus);
        dl.emplace_back(s.size());
        for (std::size_t k = 0; k < s.size(); ++k) dl[0][k] = (cache->plus[k] - cache->minus[k]) / (2 * h);
        if (ct) {
            double hp = std::min(h, 0.999 - f0), hm = std::min(h, f0 - 1e-3);
            lobe_values(s, family, alpha, f0 + hp, &cache->plus);
            lobe_values(s, family, alpha, f0 - hm, &cache->minus);
            dl.emplace_back(s.size());
            for (std::size_t k = 0; k < s.size(); ++k)
                dl[1][k] = (cache->plus[k] - cache->minus[k]) / (hp + hm);
        }
        jac.assign(3 * s.size() * std::size_t(n), 0.0);
        for (std::size_t k = 0; k < s.size(); ++k) {
            double cs = s.wi[k].z;
            for (int c = 0; c < 3; ++c) {
                double* row = &jac[(3 * k + std::size_t(c)) * std::size_t(n)];
                double inv = 1 / (1 + std::max(0.0, model(x, c, l[k])) * cs);
                row[c] = -cs * kInvPi * inv;
                row[3 + c] = -l[k] * cs * inv;
                for (std::size_t q = 0; q < dl.size(); ++q)
                    row[6 + q] = -x[3 + std::size_t(c)] * cs * dl[q][k] * inv;
            }
        }
    };
    prob.lower = {0, 0, 0, 0, 0, 0, std::log(b.alpha_lo)};
    prob.upper = {10, 10, 10, 10, 10, 10, std::log(b.alpha_hi)};
    prob.step = std::vector<double>(std::size_t(n), 1e-5);
    std::vector<double> x0 = {best.rho_d[0], best.rho_d[1], best.rho_d[2],       best.rho_s[0],
                              best.rho_s[1], best.rho_s[2], std::log(best.alpha)};
    if (ct) {
        prob.lower.push_back(1e-3);
        prob.upper.push_back(0.999);
        x0.push_back(best.f0);
    }
    LeastSquaresOptions lo;
    lo.max_iterations = max_iterations;
    LeastSquaresResult lm = levenberg_marquardt(prob, x0, lo);
    FitResult out;
    out.params.family = family;
    for (int c = 0; c < 3; ++c) {
        out.params.rho_d[c] = lm.x[std::size_t(c)];
        out.params.rho_s[c] = lm.x[3 + std::size_t(c)];
    }
    out.params.alpha = std::exp(lm.x[6]);
    out.params.f0 = ct ? lm.x[7] : 1.0;
    out.error = fit_error(s, out.params);
    out.iterations = lm.iterations;
    out.converged = lm.converged;
    out.stop = lm.stop;
    return out;
}

} // namespace illum

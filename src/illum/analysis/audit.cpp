#include "illum/analysis/audit.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/core.h>

#include "illum/analysis/stats.h"
#include "illum/analysis/weighted_histogram_test.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/common.h"
#include "illum/bsdf/microfacet.h"
#include "illum/bsdf/registry.h"
#include "illum/math/warp.h"

namespace illum {

const char* to_string(CheckStatus s) {
    switch (s) {
    case CheckStatus::Pass:
        return "pass";
    case CheckStatus::Fail:
        return "FAIL";
    case CheckStatus::Skip:
        return "skip";
    case CheckStatus::Info:
        return "info";
    }
    return "?";
}

bool AuditResult::passed() const {
    for (const auto& c : checks)
        if (c.status == CheckStatus::Fail) return false;
    return true;
}

namespace {

struct Uniform {
    std::mt19937_64 rng;
    std::uniform_real_distribution<float> dist{0.0f, 1.0f};
    explicit Uniform(std::uint64_t seed) : rng(seed) {}
    float operator()() { return std::min(dist(rng), 0x1.fffffep-1f); }
};

Vector3f sphere_dir(double theta, double phi) {
    return {float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
            float(std::cos(theta))};
}

bool finite_nonneg(Color3 c) { return c.is_finite() && !c.has_negative(); }

std::string dir_str(Vector3f w) {
    return fmt::format("(θ {:.1f}°, φ {:.1f}°)", spherical_theta(w) * 180 / kPi,
                       spherical_phi(w) * 180 / kPi);
}

std::vector<Vector3f> outgoing_directions(const BxDF& bxdf, const AuditOptions& o) {
    std::vector<Vector3f> wos;
    for (double t : o.theta_o_deg) wos.push_back(direction_deg(t, o.phi_o_deg));
    if (has_flag(bxdf.flags(), kTransmission)) wos.push_back(direction_deg(130, o.phi_o_deg));
    return wos;
}

// Accumulates a check over several cases: the first failure's detail wins.
struct Check {
    CheckResult r;
    explicit Check(std::string name) { r.name = std::move(name); }
    void fail(const std::string& why) {
        if (r.status != CheckStatus::Fail) r.detail = why;
        r.status = CheckStatus::Fail;
    }
    void note(const std::string& d) {
        if (r.status != CheckStatus::Fail) r.detail = d;
    }
};

} // namespace

ChiSquareResult chi_square_test(const BxDF& bxdf, Vector3f wo, TransportMode mode, int samples, int nt,
                                int np, std::uint64_t seed) {
    ChiSquareResult res;
    // Observed counts.
    std::vector<double> observed(std::size_t(nt) * np, 0.0);
    Uniform U(seed);
    double in_bins = 0;
    for (int i = 0; i < samples; ++i) {
        float uc = U();
        Point2f u(U(), U());
        auto s = bxdf.sample(wo, uc, u, mode);
        if (!s || s->is_specular() || !(s->pdf.value > 0)) continue;
        Vector3f w = normalize(s->wi);
        int it = std::clamp(int(spherical_theta(w) / kPi * nt), 0, nt - 1);
        int ip = std::clamp(int(spherical_phi(w) / (2 * kPi) * np), 0, np - 1);
        observed[std::size_t(it) * np + ip] += 1;
        in_bins += 1;
    }
    // Expected counts: composite Simpson with k panels per bin side. Each bin is integrated on its own,
    // with its edge nodes nudged inside by a tiny fraction of the bin, so that a pdf discontinuous on
    // a bin edge (at the horizon, say) is integrated with the limit from inside the bin.
    const int k = 12;
    const double bt = kPiD / nt, bp = 2 * kPiD / np, eps = 1e-7;
    auto wsimp = [](int i, int n) { return (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0); };
    std::vector<double> expected(observed.size());
    std::vector<double> row(std::size_t(k + 1));
    double total_expected = 0;
    for (int it = 0; it < nt; ++it) {
        double t0 = it * bt + eps * bt, t1 = (it + 1) * bt - eps * bt, ht = (t1 - t0) / k;
        for (int ip = 0; ip < np; ++ip) {
            double p0 = ip * bp + eps * bp, p1 = (ip + 1) * bp - eps * bp, hp = (p1 - p0) / k;
            double sum = 0;
            for (int a = 0; a <= k; ++a) {
                double theta = t0 + a * ht, st = std::sin(theta);
                double inner = 0;
                for (int b = 0; b <= k; ++b) {
                    double phi = p0 + b * hp;
                    inner += wsimp(b, k) * double(bxdf.pdf(wo, sphere_dir(theta, phi), mode).value);
                }
                sum += wsimp(a, k) * inner * st;
            }
            double e = sum * ht * hp / 9 * samples;
            expected[std::size_t(it) * np + ip] = e;
            total_expected += e;
        }
    }
    // The extra bin: failed and delta samples against the missing probability.
    observed.push_back(samples - in_bins);
    expected.push_back(std::max(0.0, samples - total_expected));

    // Pool bins with expected count < 5.
    double stat = 0, pool_o = 0, pool_e = 0;
    int bins = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        double o = observed[i], e = expected[i];
        if (e <= 0 && o > 0 && i + 1 < observed.size()) {
            // A bin the pdf says is (numerically) empty received samples. Only a real problem when it
            // received many; a few stray samples are pooled below.
            if (o > 5) {
                res.zero_pdf_hit = true;
                int it = int(i) / np, ip = int(i) % np;
                res.detail = fmt::format(
                    "{} samples in bin θ [{:.0f}°, {:.0f}°], φ [{:.0f}°, {:.0f}°] where ∫pdf = 0", o,
                    180.0 * it / nt, 180.0 * (it + 1) / nt, 360.0 * ip / np, 360.0 * (ip + 1) / np);
            }
        }
        if (e < 5) {
            pool_o += o;
            pool_e += e;
        } else {
            stat += sqr(o - e) / e;
            ++bins;
        }
    }
    if (pool_e > 0) {
        stat += sqr(pool_o - pool_e) / pool_e;
        ++bins;
    } else if (pool_o > 0) {
        res.zero_pdf_hit = true;
    }
    res.statistic = stat;
    res.dof = std::max(1, bins - 1);
    res.p_value = chi_square_survival(stat, res.dof);
    if (res.detail.empty())
        res.detail = fmt::format("χ² = {:.1f}, dof = {}, p = {:.3g}", stat, res.dof, res.p_value);
    return res;
}

int count_chi2_tests(const BxDF& bxdf, const AuditTraits& traits, const AuditOptions& options) {
    if (traits.delta) return 0;
    return int(outgoing_directions(bxdf, options).size());
}

AuditResult audit_bxdf(const BxDF& bxdf, const AuditTraits& traits, const AuditOptions& o) {
    AuditResult result;
    const auto wos = outgoing_directions(bxdf, o);
    const bool transmissive = has_flag(bxdf.flags(), kTransmission);
    Uniform U(o.seed);
    constexpr auto kRad = TransportMode::Radiance, kImp = TransportMode::Importance;

    // 1. Positivity (and, for delta models, f = pdf = 0 everywhere).
    {
        Check c("positivity");
        for (int i = 0; i < o.pairs; ++i) {
            Vector3f a = sample_uniform_sphere({U(), U()}), b = sample_uniform_sphere({U(), U()});
            for (auto mode : {kRad, kImp}) {
                Color3 f = bxdf.f(a, b, mode).rgb();
                float p = bxdf.pdf(a, b, mode).value;
                if (!finite_nonneg(f) || !std::isfinite(p) || p < 0)
                    c.fail(fmt::format("f = ({}, {}, {}), pdf = {} at wo {} wi {}", f.r, f.g, f.b, p,
                                       dir_str(a), dir_str(b)));
                if (traits.delta && (!f.is_black() || p != 0))
                    c.fail("delta model returns non-zero f() or pdf()");
            }
        }
        c.note(fmt::format("{} random pairs, both modes", o.pairs));
        result.checks.push_back(c.r);
    }

    // 1b. eval() gives what f() and, where it gives them, the two pdf() calls give (a model may compute
    // them together; the bidirectional connections read them from it).
    {
        Check c("eval");
        auto close = [](float x, float y) {
            return std::abs(x - y) <= 1e-5f * std::max(std::abs(x), std::abs(y));
        };
        for (int i = 0; i < o.pairs; ++i) {
            Vector3f a = sample_uniform_sphere({U(), U()}), b = sample_uniform_sphere({U(), U()});
            if (a.z == 0 || b.z == 0) continue;
            for (auto mode : {kRad, kImp}) {
                const BSDFEval e = bxdf.eval(a, b, mode);
                const Color3 fe = e.f.rgb(), f = bxdf.f(a, b, mode).rgb();
                const float p_ab = bxdf.pdf(a, b, kRad).value, p_ba = bxdf.pdf(b, a, kRad).value;
                if (!close(fe.r, f.r) || !close(fe.g, f.g) || !close(fe.b, f.b) ||
                    (e.has_pdfs && (!close(e.pdf_wi, p_ab) || !close(e.pdf_wo, p_ba))))
                    c.fail(
                        fmt::format("eval gives f = ({}, {}, {}), pdfs {} {}; f() ({}, {}, {}), pdf() {} {} "
                                    "at wo {} wi {}",
                                    fe.r, fe.g, fe.b, e.pdf_wi, e.pdf_wo, f.r, f.g, f.b, p_ab, p_ba,
                                    dir_str(a), dir_str(b)));
            }
        }
        c.note(fmt::format("{} random pairs, both modes", o.pairs));
        result.checks.push_back(c.r);
    }

    // 2. Reciprocity.
    {
        Check c("reciprocity");
        if (traits.delta) {
            c.r.status = CheckStatus::Skip;
            c.r.detail = "delta lobes (directions checked below)";
        } else if (!traits.not_reciprocal.empty()) {
            c.r.status = CheckStatus::Skip;
            c.r.detail = "not reciprocal: " + traits.not_reciprocal;
        } else if (traits.stochastic) {
            // f is a stochastic estimate: compare f(a,b) - f(b,a) with a the more normal direction, whose
            // mean must vanish for a reciprocal model (a systematic asymmetry would not).
            double sd = 0, sd2 = 0, sf = 0;
            int n = 0;
            for (int i = 0; i < o.pairs * 4; ++i) {
                Vector3f a = sample_uniform_hemisphere({U(), U()}), b = sample_uniform_hemisphere({U(), U()});
                if (a.z < b.z) std::swap(a, b);
                double fab = bxdf.f(a, b, kRad).rgb().luminance(), fba = bxdf.f(b, a, kRad).rgb().luminance();
                double d = fab - fba;
                sd += d;
                sd2 += d * d;
                sf += 0.5 * (fab + fba);
                ++n;
            }
            double mean = sd / n, se = std::sqrt(std::max(0.0, sd2 / n - mean * mean) / n), mf = sf / n;
            c.r.value = mf > 0 ? mean / mf : 0; // relative to the mean f
            c.r.standard_error = mf > 0 ? se / mf : 0;
            std::string d = fmt::format("stochastic: mean f(n,g) - f(g,n) = {:.4g} ± {:.2g} (mean f {:.4g})",
                                        mean, se, mf);
            if (std::abs(mean) > 4.5 * se)
                c.fail(d);
            else
                c.note(d);
        } else {
            double worst = 0;
            std::string worst_detail;
            int tested = 0;
            for (int i = 0; i < o.pairs; ++i) {
                Vector3f a = sample_uniform_sphere({U(), U()}), b = sample_uniform_sphere({U(), U()});
                if (!transmissive && !same_hemisphere(a, b)) b.z = -b.z;
                Color3 fab = bxdf.f(a, b, kRad).rgb(), fba = bxdf.f(b, a, kRad).rgb();
                Color3 lhs = fab, rhs = fba;
                if (!same_hemisphere(a, b)) {
                    // Generalised reciprocity f(wo,wi)/η_o² = f(wi,wo)/η_i² in radiance mode.
                    float ea = a.z > 0 ? 1 : traits.eta, eb = b.z > 0 ? 1 : traits.eta;
                    lhs = fab / (ea * ea);
                    rhs = fba / (eb * eb);
                    // Adjointness: importance mode is the transpose of radiance mode.
                    Color3 adj = bxdf.f(b, a, kImp).rgb();
                    for (int ch = 0; ch < 3; ++ch) {
                        double err = std::abs(fab[ch] - adj[ch]) / (std::max(fab[ch], adj[ch]) + 1e-4);
                        if (err > worst) {
                            worst = err;
                            worst_detail = fmt::format(
                                "adjoint: f_rad(wo,wi) = {:.5g}, f_imp(wi,wo) = {:.5g} at wo {} wi {}",
                                fab[ch], adj[ch], dir_str(a), dir_str(b));
                        }
                    }
                }
                for (int ch = 0; ch < 3; ++ch) {
                    double err = std::abs(lhs[ch] - rhs[ch]) / (std::max(lhs[ch], rhs[ch]) + 1e-4);
                    if (err > worst) {
                        worst = err;
                        worst_detail = fmt::format("f(wo,wi) = {:.5g}, f(wi,wo) = {:.5g}{} at wo {} wi {}",
                                                   lhs[ch], rhs[ch], same_hemisphere(a, b) ? "" : " (/η²)",
                                                   dir_str(a), dir_str(b));
                    }
                }
                ++tested;
            }
            c.r.value = worst;
            std::string d =
                fmt::format("{} pairs{}, worst relative difference {:.2g}", tested,
                            transmissive ? " incl. transmission (generalised, adjoint)" : "", worst);
            if (worst > 5e-3) {
                if (traits.non_physical) {
                    c.r.status = CheckStatus::Info;
                    c.r.detail = "not required (non-physical): " + d + "; " + worst_detail;
                } else {
                    c.fail(d + "; " + worst_detail);
                }
            } else {
                c.note(d);
            }
        }
        result.checks.push_back(c.r);
    }

    // 3. sample() against f()/pdf() (or, for delta lobes, against the mirror/refraction directions).
    {
        Check c(traits.delta ? "delta-directions" : "sample-consistency");
        int n = 0, specular = 0;
        for (std::size_t k = 0; k < wos.size(); ++k) {
            Vector3f wo = wos[k];
            for (int i = 0; i < 2000; ++i) {
                float uc = U();
                Point2f u(U(), U());
                for (auto mode : {kRad, kImp}) {
                    auto s = bxdf.sample(wo, uc, u, mode);
                    if (!s) continue;
                    ++n;
                    Color3 w = s->weight().rgb();
                    if (!finite_nonneg(w) || !(s->pdf.value > 0) || !is_finite(s->wi)) {
                        c.fail(fmt::format("bad sample at wo {}: weight ({}, {}, {}), pdf {}", dir_str(wo),
                                           w.r, w.g, w.b, s->pdf.value));
                        continue;
                    }
                    bool refl = same_hemisphere(wo, s->wi);
                    if (refl != s->is_reflection() || refl == s->is_transmission())
                        c.fail(fmt::format("flags say {} but wi {} is on the {} side of wo {}",
                                           s->is_reflection() ? "reflection" : "transmission", dir_str(s->wi),
                                           refl ? "same" : "other", dir_str(wo)));
                    if (s->is_specular()) {
                        ++specular;
                        Vector3f expect = reflect_z(wo);
                        if (!refl) {
                            float etap;
                            if (traits.eta == 1)
                                expect = -wo;
                            else if (!refract(wo, Vector3f(0, 0, 1), traits.eta, &etap, &expect))
                                c.fail("transmission sampled under total internal reflection at wo " +
                                       dir_str(wo));
                        }
                        if (length(s->wi - expect) > 1e-4f)
                            c.fail(fmt::format("specular wi {} is not the {} direction {} of wo {}",
                                               dir_str(s->wi), refl ? "mirror" : "refraction",
                                               dir_str(expect), dir_str(wo)));
                        continue;
                    }
                    if (traits.delta) {
                        c.fail("delta model returned a non-specular sample");
                        continue;
                    }
                    if (traits.stochastic || s->pdf_is_proportional) continue;
                    Color3 f = bxdf.f(wo, s->wi, mode).rgb();
                    float p = bxdf.pdf(wo, s->wi, mode).value;
                    float perr = std::abs(p - s->pdf.value) / std::max(p, s->pdf.value);
                    if (perr > 1e-3f)
                        c.fail(fmt::format("pdf() = {:.6g} but sample() says {:.6g} at wo {} wi {}", p,
                                           s->pdf.value, dir_str(wo), dir_str(s->wi)));
                    for (int ch = 0; ch < 3; ++ch) {
                        float ferr = std::abs(f[ch] - s->f[ch]) / (std::max(f[ch], s->f[ch]) + 1e-6f);
                        if (ferr > 1e-3f)
                            c.fail(fmt::format("f() = {:.6g} but sample() says {:.6g} at wo {} wi {}", f[ch],
                                               s->f[ch], dir_str(wo), dir_str(s->wi)));
                    }
                }
            }
        }
        c.note(fmt::format("{} samples ({} specular) over {} directions wo", n, specular, wos.size()));
        if (traits.stochastic && c.r.status != CheckStatus::Fail)
            c.r.detail += "; stochastic: f/pdf equality not applicable";
        result.checks.push_back(c.r);
    }

    // 4. Energy: albedo <= 1 (= 1 for lossless models), MC (sample weights) against quadrature of f.
    {
        Check e("energy"), q("energy-quadrature");
        double worst_albedo = 0, worst_se = 0;
        std::string quad_detail;
        for (std::size_t k = 0; k < wos.size(); ++k) {
            Vector3f wo = wos[k];
            Rgb64 mean, se;
            Rgb64 ns_mean, ns_se; // the part of the MC estimate from non-delta samples, which f() describes
            albedo_monte_carlo(bxdf, wo, o.energy_samples, o.seed + 7 * k + 1, &mean, &se, kImp, &ns_mean,
                               &ns_se);
            for (int ch = 0; ch < 3; ++ch) {
                if (mean[ch] > worst_albedo) {
                    worst_albedo = mean[ch];
                    worst_se = se[ch];
                }
                if (mean[ch] > 1 + 4 * se[ch] + 1e-3) {
                    std::string d =
                        fmt::format("albedo {:.4f} ± {:.4f} > 1 at wo {}", mean[ch], se[ch], dir_str(wo));
                    if (traits.non_physical) {
                        e.r.status = CheckStatus::Info;
                        e.r.detail = "not required (non-physical): " + d;
                    } else {
                        e.fail(d);
                    }
                }
                if (traits.lossless && std::abs(mean[ch] - 1) > 4 * se[ch] + 2e-3)
                    e.fail(fmt::format("lossless model has albedo {:.4f} ± {:.4f} at wo {}", mean[ch], se[ch],
                                       dir_str(wo)));
            }
            if (!traits.delta) {
                Rgb64 quad = albedo_quadrature(bxdf, wo, o.quadrature_theta,
                                               !has_flag(bxdf.flags(), kTransmission), kImp);
                for (int ch = 0; ch < 3; ++ch) {
                    double tol =
                        5 * ns_se[ch] + 0.01 * std::max(1.0, quad[ch]) + (traits.stochastic ? 0.01 : 0.0);
                    std::string d = fmt::format("quadrature {:.4f} vs MC {:.4f} ± {:.4f} at wo {}", quad[ch],
                                                ns_mean[ch], ns_se[ch], dir_str(wo));
                    if (std::abs(quad[ch] - ns_mean[ch]) > tol)
                        q.fail(d);
                    else if (k == 0 && ch == 0)
                        quad_detail = d;
                }
            }
        }
        e.r.value = worst_albedo;
        e.r.standard_error = worst_se;
        if (e.r.status == CheckStatus::Pass)
            e.r.detail =
                fmt::format("max albedo {:.4f}{}", worst_albedo, traits.lossless ? " (lossless: = 1)" : "");
        result.checks.push_back(e.r);
        if (traits.delta) {
            q.r.status = CheckStatus::Skip;
            q.r.detail = "delta lobes: no quadrature of f";
        } else {
            q.note(quad_detail);
        }
        result.checks.push_back(q.r);
    }

    // 5. Chi-square test of sample() against pdf().
    {
        Check c("chi-square");
        if (traits.delta) {
            c.r.status = CheckStatus::Skip;
            c.r.detail = "delta lobes";
        } else if (traits.stochastic) {
            // pdf() is approximate: test sample()'s weights against f() instead (weighted_histogram_test.h).
            c = Check("sample-vs-f");
            double alpha = sidak_significance(o.significance, std::max(1, o.chi2_tests));
            double min_p = 1;
            for (std::size_t k = 0; k < wos.size(); ++k) {
                auto r =
                    weighted_histogram_test(bxdf, wos[k], kRad, o.weighted_samples, o.weighted_cos_bins,
                                            o.weighted_phi_bins, o.weighted_f_per_bin, o.seed + 2000 + k);
                ++result.chi2_tests;
                min_p = std::min(min_p, r.p_value);
                if (r.p_value < alpha)
                    c.fail(fmt::format("wo {}: {} (threshold p {:.2g})", dir_str(wos[k]), r.detail, alpha));
            }
            c.note(fmt::format("{} weighted-histogram tests, min p = {:.3g}, Sidak threshold {:.2g}",
                               wos.size(), min_p, alpha));
        } else {
            double alpha = sidak_significance(o.significance, std::max(1, o.chi2_tests));
            double min_p = 1;
            for (std::size_t k = 0; k < wos.size(); ++k) {
                auto r = chi_square_test(bxdf, wos[k], kRad, o.chi2_samples, o.chi2_theta_bins,
                                         o.chi2_phi_bins, o.seed + 1000 + k);
                ++result.chi2_tests;
                min_p = std::min(min_p, r.p_value);
                if (r.zero_pdf_hit || r.p_value < alpha)
                    c.fail(fmt::format("wo {}: {} (threshold p {:.2g})", dir_str(wos[k]), r.detail, alpha));
            }
            c.note(fmt::format("{} tests, min p = {:.3g}, Sidak threshold {:.2g}", wos.size(), min_p, alpha));
        }
        result.checks.push_back(c.r);
    }
    return result;
}

namespace {

AuditTraits case_traits(const ModelSpec& model, const AuditCase& c, const ParamValues& v) {
    AuditTraits t;
    t.delta = model.delta;
    t.lossless = c.lossless;
    t.non_physical = model.non_physical;
    t.stochastic = model.stochastic;
    t.eta = model_eta(model, v);
    t.not_reciprocal = model.not_reciprocal;
    return t;
}

} // namespace

AuditResult audit_case(const ModelSpec& model, const AuditCase& c, const AuditOptions& options) {
    ParamValues v = resolve_params(model, c.params);
    auto bxdf = model.make(v);
    AuditResult r = audit_bxdf(*bxdf, case_traits(model, c, v), options);
    r.model = model.name;
    for (const auto& [k, value] : c.params) r.params += (r.params.empty() ? "" : " ") + k + "=" + value;
    if (r.params.empty()) r.params = "(defaults)";
    return r;
}

std::vector<AuditResult> audit_model(const ModelSpec& model, AuditOptions options) {
    if (options.chi2_tests <= 1) {
        int tests = 0;
        for (const auto& c : model.audit_grid) {
            ParamValues v = resolve_params(model, c.params);
            tests += count_chi2_tests(*model.make(v), case_traits(model, c, v), options);
        }
        options.chi2_tests = std::max(1, tests);
    }
    std::vector<AuditResult> out;
    for (const auto& c : model.audit_grid) out.push_back(audit_case(model, c, options));
    return out;
}

} // namespace illum

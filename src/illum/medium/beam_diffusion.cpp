#include "illum/medium/beam_diffusion.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace illum {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// Gauss-Legendre nodes and weights on [-1, 1], by Newton's method on P_n (Golub-Welsch would do as well).
template <int N>
struct GaussLegendre {
    std::array<double, N> x{}, w{};
    GaussLegendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(kPiD * (i + 0.75) / (N + 0.5)), dp = 1;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = z; // P_0, P_1, then the recurrence up to P_N
                for (int k = 2; k <= N; ++k) {
                    double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = N * (z * p1 - p0) / (z * z - 1);
                double dz = p1 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-15) break;
            }
            x[i] = z;
            w[i] = 2 / ((1 - z * z) * dp * dp);
        }
    }
};

const GaussLegendre<8>& gl8() {
    static const GaussLegendre<8> rule;
    return rule;
}

// ∫_a^b f(x) dx with `panels` equal Gauss-Legendre panels.
template <typename F>
double integrate_linear(F&& f, double a, double b, int panels) {
    const auto& q = gl8();
    double h = (b - a) / panels, sum = 0;
    for (int p = 0; p < panels; ++p) {
        double mid = a + (p + 0.5) * h;
        for (int i = 0; i < 8; ++i) sum += q.w[i] * f(mid + 0.5 * h * q.x[i]);
    }
    return sum * 0.5 * h;
}

// ∫_a^b f(x) dx over x = e^u (0 < a < b), `per_efold` panels per factor e.
template <typename F>
double integrate_log(F&& f, double a, double b, double per_efold) {
    if (!(b > a)) return 0;
    double la = std::log(a), lb = std::log(b);
    int panels = std::max(1, int(std::ceil((lb - la) * per_efold)));
    return integrate_linear(
        [&](double u) {
            double x = std::exp(u);
            return f(x) * x;
        },
        la, lb, panels);
}

// ∫_0^b f over [0, a] (f varies on the scale a there) and [a, b] log-spaced. On [0, a], x = a v²: the
// single-scattering integrand behaves as √x at x = 0 (the Fresnel transmittance at the critical angle),
// which the substitution makes smooth.
template <typename F>
double integrate_half_line(F&& f, double a, double b, int refine) {
    a = std::min(a, b);
    auto g = [&](double v) { return f(a * v * v) * 2 * a * v; };
    return integrate_linear(g, 0, 1, refine) + integrate_log(f, a, b, 0.5 * refine);
}

// Henyey-Greenstein for the cosine between the directions of travel before and after scattering.
double hg(double cos_theta, double g) {
    double d = 1 + g * g - 2 * g * cos_theta;
    return (1 - g * g) / (4 * kPiD * d * std::sqrt(d));
}

// e^{-x} is below 1e-26 beyond this: the integrals' upper limits, in units of the decay length.
constexpr double kTail = 60;

double ss(double sigma_s, double sigma_a, double g, double eta, double r, int refine) {
    double sigma_t = sigma_s + sigma_a;
    if (sigma_s <= 0 || r * sigma_t > kTail) return 0; // e^{-σ_t d}, d ≥ r
    double t_c = eta > 1 ? r * std::sqrt(eta * eta - 1) : 0;
    auto f = [&](double x) { // x = t - t_c
        double t = t_c + x, d = std::sqrt(r * r + t * t), c = t / d;
        return sigma_s * std::exp(-sigma_t * (t + d)) / (d * d) * hg(-c, g) *
               (1 - fresnel_dielectric_from_inside(c, eta)) * c;
    };
    double scale = std::min(std::max(r, 1e-300), 1 / sigma_t);
    return integrate_half_line(f, 0.5 * scale, kTail / sigma_t, refine);
}

double ms(double sigma_s, double sigma_a, double g, double eta, double r, int refine) {
    double sp_s = (1 - g) * sigma_s, sp_t = sigma_a + sp_s;
    if (sp_s <= 0) return 0;
    double rho_p = sp_s / sp_t;
    double D = (2 * sigma_a + sp_s) / (3 * sp_t * sp_t);
    double sigma_tr = std::sqrt(std::max(0.0, sigma_a / D));
    double f1 = fresnel_moment1(eta), f2 = fresnel_moment2(eta);
    double ze = -2 * D * (1 + 3 * f2) / (1 - 2 * f1);
    double c_phi = 0.25 * (1 - 2 * f1), c_e = 0.5 * (1 - 3 * f2);
    auto f = [&](double z) {
        double zv = 2 * ze - z;
        double dr = std::sqrt(r * r + z * z), dv = std::sqrt(r * r + zv * zv);
        double er = std::exp(-sigma_tr * dr), ev = std::exp(-sigma_tr * dv);
        double phi = (er / dr - ev / dv) / (4 * kPiD * D);
        double en =
            (z * (1 + sigma_tr * dr) * er / (dr * dr * dr) - zv * (1 + sigma_tr * dv) * ev / (dv * dv * dv)) /
            (4 * kPiD);
        double kappa = 1 - std::exp(-2 * sp_t * (dr + z));
        return sp_t * std::exp(-sp_t * z) * rho_p * rho_p * kappa * (c_phi * phi + c_e * en);
    };
    double scale = std::min({std::max(r, 1e-300), 1 / sp_t, std::abs(ze)});
    return integrate_half_line(f, 0.5 * scale, kTail / sp_t, refine);
}

} // namespace

double fresnel_moment1(double eta) {
    double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1) return 0.45966 - 1.73965 * eta + 3.37668 * e2 - 3.904945 * e3 + 2.49277 * e4 - 0.68441 * e5;
    return -4.61686 + 11.1136 * eta - 10.4646 * e2 + 5.11455 * e3 - 1.27198 * e4 + 0.12746 * e5;
}

double fresnel_moment2(double eta) {
    double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1) return 0.27614 - 0.87350 * eta + 1.12077 * e2 - 0.65095 * e3 + 0.07883 * e4 + 0.04860 * e5;
    double i1 = 1 / eta, i2 = i1 * i1, i3 = i2 * i1;
    return -547.033 + 45.3087 * i3 - 218.725 * i2 + 458.843 * i1 + 404.557 * eta - 189.519 * e2 +
           54.9327 * e3 - 9.00603 * e4 + 0.63942 * e5;
}

double fresnel_dielectric_from_inside(double cos_inside, double eta) {
    double ci = std::clamp(cos_inside, 0.0, 1.0);
    double sin2_t = eta * eta * (1 - ci * ci); // Snell: sin θ_t = η sin θ_i
    if (sin2_t >= 1) return 1;
    double ct = std::sqrt(1 - sin2_t), n = 1 / eta; // n = outside / inside
    double r_par = (n * ci - ct) / (n * ci + ct), r_perp = (ci - n * ct) / (ci + n * ct);
    return 0.5 * (r_par * r_par + r_perp * r_perp);
}

double beam_diffusion_ss(double sigma_s, double sigma_a, double g, double eta, double r) {
    return ss(sigma_s, sigma_a, g, eta, r, 1);
}

double beam_diffusion_ms(double sigma_s, double sigma_a, double g, double eta, double r) {
    return ms(sigma_s, sigma_a, g, eta, r, 1);
}

double pbd_effective_albedo(double albedo, double g, double eta, int refine) {
    albedo = std::clamp(albedo, 0.0, 1.0);
    if (albedo <= 0) return 0;
    double sigma_s = albedo, sigma_a = 1 - albedo; // σ_t = 1: ρ_eff does not depend on the length scale
    // The profile decays as e^{-σ_tr r} (as r^-3 for α = 1): integrate to where the tail is negligible.
    double sp_s = (1 - g) * sigma_s, sp_t = sigma_a + sp_s;
    double D = (2 * sigma_a + sp_s) / (3 * sp_t * sp_t), sigma_tr = std::sqrt(sigma_a / D);
    double r_max = std::min(1e5, kTail / std::max(sigma_tr, 1e-300) + kTail / sp_t);
    auto f = [&](double r) {
        return 2 * kPiD * r *
               (ss(sigma_s, sigma_a, g, eta, r, refine) + ms(sigma_s, sigma_a, g, eta, r, refine));
    };
    // 2πr S(r) tends to a constant as r → 0 (S_ss ~ 1/r): the part below 1e-9 is negligible.
    return integrate_log(f, 1e-9, r_max, 0.5 * refine);
}

EffectiveAlbedoTable::EffectiveAlbedoTable(float eta, float g, int nodes) : eta_(eta), g_(g) {
    int n = std::max(nodes, 4);
    s_.resize(n);
    albedo_.resize(n);
    rho_.resize(n);
    slope_.resize(n);
    for (int i = 0; i < n; ++i) {
        s_[i] = double(i) / (n - 1); // s = 1 - √(1 - α), uniform
        albedo_[i] = 1 - (1 - s_[i]) * (1 - s_[i]);
        rho_[i] = pbd_effective_albedo(albedo_[i], g, eta);
    }
    // Monotone cubic Hermite slopes (Fritsch & Carlson 1980, "Monotone Piecewise Cubic Interpolation").
    double h = 1.0 / (n - 1);
    std::vector<double> delta(n - 1);
    for (int i = 0; i + 1 < n; ++i) delta[i] = (rho_[i + 1] - rho_[i]) / h;
    slope_[0] = delta[0];
    slope_[n - 1] = delta[n - 2];
    for (int i = 1; i + 1 < n; ++i)
        slope_[i] = delta[i - 1] * delta[i] <= 0 ? 0 : 0.5 * (delta[i - 1] + delta[i]);
    for (int i = 0; i + 1 < n; ++i) {
        if (delta[i] == 0) {
            slope_[i] = slope_[i + 1] = 0;
            continue;
        }
        double a = slope_[i] / delta[i], b = slope_[i + 1] / delta[i], q = a * a + b * b;
        if (q > 9) {
            double tau = 3 / std::sqrt(q);
            slope_[i] = tau * a * delta[i];
            slope_[i + 1] = tau * b * delta[i];
        }
    }
}

double EffectiveAlbedoTable::hermite(int i, double t) const {
    double h = s_[i + 1] - s_[i], t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * rho_[i] + (t3 - 2 * t2 + t) * h * slope_[i] +
           (-2 * t3 + 3 * t2) * rho_[i + 1] + (t3 - t2) * h * slope_[i + 1];
}

float EffectiveAlbedoTable::effective_albedo(float albedo) const {
    double a = std::clamp(double(albedo), 0.0, 1.0);
    double s = 1 - std::sqrt(1 - a);
    int n = int(s_.size());
    int i = std::min(int(s * (n - 1)), n - 2);
    return float(hermite(i, (s - s_[i]) / (s_[i + 1] - s_[i])));
}

float EffectiveAlbedoTable::albedo(float rho_eff) const {
    if (!(rho_eff > rho_.front())) return 0;
    if (!(rho_eff < rho_.back())) return 1;
    // The last node whose value is ≤ rho_eff, then the spline's root in that interval by bisection (the
    // monotone spline is non-decreasing there; 50 halvings are below double precision of t).
    int i = int(std::upper_bound(rho_.begin(), rho_.end(), double(rho_eff)) - rho_.begin()) - 1;
    i = std::clamp(i, 0, int(rho_.size()) - 2);
    double lo = 0, hi = 1;
    for (int it = 0; it < 50; ++it) {
        double mid = 0.5 * (lo + hi);
        (hermite(i, mid) < rho_eff ? lo : hi) = mid;
    }
    double s = s_[i] + 0.5 * (lo + hi) * (s_[i + 1] - s_[i]);
    return float(1 - (1 - s) * (1 - s));
}

} // namespace illum

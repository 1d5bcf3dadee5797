#include "illum/radiometry/conductor_rgb.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <mutex>

namespace illum {

namespace {

constexpr double kPiD = 3.14159265358979323846;

// The wavelength grid of the reflectance spectra: the 1 nm grid unbounded_spectrum_to_rgb integrates on.
constexpr int kLambdaFirst = 360, kLambdaLast = 830;

// Incidence angles of the fit: θ = 0.5°, 1.5°, ..., 89.5° (midpoints of 1° bins), weighted by
// cos θ sin θ — the share of each bin in the cosine-weighted hemisphere, i.e. in a directional albedo.
constexpr int kAngles = 90;
struct AngleSample {
    double cos_theta, weight;
};
std::array<AngleSample, kAngles> fit_angles() {
    std::array<AngleSample, kAngles> a{};
    for (int j = 0; j < kAngles; ++j) {
        double t = (j + 0.5) * kPiD / 180;
        a[std::size_t(j)] = {std::cos(t), std::cos(t) * std::sin(t)};
    }
    return a;
}

// On the curve of (η, k) with normal-incidence reflectance r0: ((η-1)² + k²)/((η+1)² + k²) = r0
// solved for k² = (r0 (η+1)² - (η-1)²)/(1 - r0), which is >= 0 for η between
// (1 - √r0)/(1 + √r0) and (1 + √r0)/(1 - √r0).
double k_on_f0_curve(double eta, double r0) {
    return std::sqrt(std::max(0.0, (r0 * (eta + 1) * (eta + 1) - (eta - 1) * (eta - 1)) / (1 - r0)));
}

// Bounds from the range a material's measured η and k span in the visible (380..780 nm): a fitted RGB η
// stays within [eta_lo, eta_hi] and k below k_hi, so that it remains a plausible index of that material
// (without them, an out-of-gamut channel drives the fit to degenerate indices such as η = 0.49, k = 44).
struct IndexBox {
    double eta_lo, eta_hi, k_hi;
};
IndexBox visible_box(const MeasuredIndex& m) {
    IndexBox b{m.eta(380), m.eta(380), m.k(380)};
    for (int l = 381; l <= 780; ++l)
        b.eta_lo = std::min(b.eta_lo, m.eta(l)), b.eta_hi = std::max(b.eta_hi, m.eta(l)),
        b.k_hi = std::max(b.k_hi, m.k(l));
    return b;
}

// Per channel: the (η, k) within the bounds with F(0°) = r0 exactly that minimises Σ w (F(θ) - target(θ))²:
// a scan of log η along the curve F(0°) = r0 where it lies within the bounds, then golden-section refinement
// around the best node.
//
// A Fresnel reflectance cannot exceed 1, but the RGB of a saturated spectral reflectance can (gold's red
// channel at normal incidence is 1.02: its colour lies outside the sRGB gamut). When r0 is beyond what
// the bounds allow, the most reflective index within them (smallest η, largest k) is taken.
std::pair<double, double> fit_channel(double r0, const std::array<double, kAngles>& target,
                                      const IndexBox& box) {
    static const std::array<AngleSample, kAngles> angles = fit_angles();
    constexpr double kTolK = 0.01; // k below 0.01 changes F by < 1e-4: a dielectric may take a tiny k
    r0 = std::clamp(r0, 1e-4, 0.9999);
    double s = std::sqrt(r0);
    double lo = std::max(std::log((1 - s) / (1 + s)), std::log(box.eta_lo));
    double hi = std::min(std::log((1 + s) / (1 - s)), std::log(box.eta_hi));
    auto feasible = [&](double log_eta) {
        double k = k_on_f0_curve(std::exp(log_eta), r0);
        return k <= box.k_hi + kTolK;
    };
    auto error = [&](double log_eta) {
        if (!feasible(log_eta)) return HUGE_VAL;
        double eta = std::exp(log_eta), k = k_on_f0_curve(eta, r0), e = 0;
        for (std::size_t j = 0; j < kAngles; ++j) {
            double d = fresnel_conductor_exact(angles[j].cos_theta, eta, k) - target[j];
            e += angles[j].weight * d * d;
        }
        return e;
    };
    constexpr int kScan = 400;
    auto node = [&](int i) { return lo + (hi - lo) * i / kScan; };
    int best = -1;
    double best_e = HUGE_VAL;
    for (int i = 0; i <= kScan && lo <= hi; ++i) {
        double e = error(node(i));
        if (e < best_e) best_e = e, best = i;
    }
    if (best < 0) return {box.eta_lo, box.k_hi}; // r0 out of reach within the bounds
    double a = node(std::max(0, best - 1)), b = node(std::min(kScan, best + 1));
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 60; ++it) {
        double c = b - g * (b - a), d = a + g * (b - a);
        if (error(c) < error(d))
            b = d;
        else
            a = c;
    }
    double x = 0.5 * (a + b);
    if (!feasible(x)) x = node(best);
    double eta = std::exp(x);
    return {eta, k_on_f0_curve(eta, r0)};
}

} // namespace

double fresnel_conductor_exact(double cos_theta, double eta, double k) {
    using C = std::complex<double>;
    double c = std::clamp(std::abs(cos_theta), 0.0, 1.0), s2 = 1 - c * c;
    C n(eta, k);
    C cos_t = std::sqrt(C(1) - s2 / (n * n));
    C rs = (c - n * cos_t) / (c + n * cos_t);
    C rp = (n * c - cos_t) / (n * c + cos_t);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

Color3 reflectance_rgb(const MeasuredIndex& m, double cos_theta) {
    PiecewiseLinearSpectrum f;
    for (int l = kLambdaFirst; l <= kLambdaLast; ++l) {
        f.lambda.push_back(l);
        f.value.push_back(fresnel_conductor_exact(cos_theta, m.eta(l), m.k(l)));
    }
    return unbounded_spectrum_to_rgb(f);
}

ConductorRgb integrated_index_rgb(const MeasuredIndex& m) {
    // η and k are positive; the sRGB reduction of a non-negative spectrum can dip slightly below 0
    // in a channel the spectrum does not reach (k of TiO2 is non-zero only below 420 nm).
    return {clamp(unbounded_spectrum_to_rgb(m.eta), 1e-3f, 1e3f),
            clamp(unbounded_spectrum_to_rgb(m.k), 0.0f, 1e3f)};
}

ConductorRgb fitted_index_rgb(const MeasuredIndex& m) {
    static const std::array<AngleSample, kAngles> angles = fit_angles();
    std::array<Color3, kAngles> truth{};
    for (int j = 0; j < kAngles; ++j)
        truth[std::size_t(j)] = reflectance_rgb(m, angles[std::size_t(j)].cos_theta);
    Color3 r0 = reflectance_rgb(m, 1.0);
    IndexBox box = visible_box(m);
    ConductorRgb out;
    for (int c = 0; c < 3; ++c) {
        std::array<double, kAngles> target{};
        for (int j = 0; j < kAngles; ++j) target[std::size_t(j)] = truth[std::size_t(j)][c];
        auto [eta, k] = fit_channel(r0[c], target, box);
        out.eta[c] = float(eta);
        out.k[c] = float(k);
    }
    return out;
}

const ConductorRgb* named_conductor_rgb(std::string_view element) {
    // Each element is fitted on its first use (about 20 ms), so a scene pays only for the metals it names.
    constexpr std::size_t kMax = 7;
    static std::array<std::once_flag, kMax> once;
    static std::array<ConductorRgb, kMax> reduced{};
    auto all = measured_indices();
    for (std::size_t i = 0; i < all.size() && i < kMax; ++i)
        if (all[i].element == element) {
            std::call_once(once[i], [&] { reduced[i] = fitted_index_rgb(all[i]); });
            return &reduced[i];
        }
    return nullptr;
}

} // namespace illum

#include "illum/radiometry/sigmoid_fit.h"

#include <algorithm>
#include <cmath>

#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

// Solves the 3x3 system A x = b by Cramer's rule; false if A is (numerically) singular.
bool solve3(const double A[9], const double b[3], double x[3]) {
    double c00 = A[4] * A[8] - A[5] * A[7], c01 = A[5] * A[6] - A[3] * A[8], c02 = A[3] * A[7] - A[4] * A[6];
    double det = A[0] * c00 + A[1] * c01 + A[2] * c02;
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) return false;
    double d0 = b[0] * c00 + A[1] * (A[5] * b[2] - b[1] * A[8]) + A[2] * (b[1] * A[7] - A[4] * b[2]);
    double d1 = A[0] * (b[1] * A[8] - A[5] * b[2]) + b[0] * c01 + A[2] * (A[3] * b[2] - b[1] * A[6]);
    double d2 = A[0] * (A[4] * b[2] - b[1] * A[7]) + A[1] * (b[1] * A[6] - A[3] * b[2]) + b[0] * c02;
    x[0] = d0 / det;
    x[1] = d1 / det;
    x[2] = d2 / det;
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// CIELAB's f(t) = t^(1/3) above (6/29)³, t / (3 (6/29)²) + 4/29 below, and its derivative.
void lab_f(double t, double& f, double& df) {
    constexpr double d = 6.0 / 29, d3 = d * d * d;
    if (t > d3) {
        f = std::cbrt(t);
        df = 1 / (3 * f * f);
    } else {
        df = 1 / (3 * d * d);
        f = t * df + 4.0 / 29;
    }
}

// The sums over the grid, the generator's inner loop. They vectorise under -fopenmp-simd and
// -fno-math-errno (cmake/rgb2spec.cmake); with GCC on x86-64 a second version for AVX2 is chosen at
// load time where the CPU has them (twice the doubles per instruction).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define ILLUM_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define ILLUM_SIMD_CLONES
#endif

ILLUM_SIMD_CLONES void sums(int n, const double* u, const double* w0, const double* w1, const double* w2,
                            double a, double b, double d, double out[3]) {
    double r0 = 0, r1 = 0, r2 = 0;
#pragma omp simd reduction(+ : r0, r1, r2)
    for (int i = 0; i < n; ++i) {
        double x = (a * u[i] + b) * u[i] + d;
        double s = 0.5 + 0.5 * x / std::sqrt(1 + x * x);
        r0 += s * w0[i], r1 += s * w1[i], r2 += s * w2[i];
    }
    out[0] = r0, out[1] = r1, out[2] = r2;
}

ILLUM_SIMD_CLONES void sums_and_jacobian(int n, const double* u, const double* w0, const double* w1,
                                         const double* w2, double a, double b, double d, double out[3],
                                         double jac[9]) {
    double r0 = 0, r1 = 0, r2 = 0;
    double j0 = 0, j1 = 0, j2 = 0, j3 = 0, j4 = 0, j5 = 0, j6 = 0, j7 = 0, j8 = 0;
#pragma omp simd reduction(+ : r0, r1, r2, j0, j1, j2, j3, j4, j5, j6, j7, j8)
    for (int i = 0; i < n; ++i) {
        double x = (a * u[i] + b) * u[i] + d;
        double rs = 1 / std::sqrt(1 + x * x);
        double s = 0.5 + 0.5 * x * rs, ds = 0.5 * rs * rs * rs; // S(x), S'(x)
        double d1 = ds * u[i], d0 = d1 * u[i];
        r0 += s * w0[i], r1 += s * w1[i], r2 += s * w2[i];
        j0 += d0 * w0[i], j1 += d1 * w0[i], j2 += ds * w0[i];
        j3 += d0 * w1[i], j4 += d1 * w1[i], j5 += ds * w1[i];
        j6 += d0 * w2[i], j7 += d1 * w2[i], j8 += ds * w2[i];
    }
    out[0] = r0, out[1] = r1, out[2] = r2;
    jac[0] = j0, jac[1] = j1, jac[2] = j2, jac[3] = j3, jac[4] = j4, jac[5] = j5, jac[6] = j6, jac[7] = j7;
    jac[8] = j8;
}

} // namespace

SigmoidFit::SigmoidFit(const RGBColorSpace& space, FitResidual residual, double step_nm)
    : space_(space), mode_(residual) {
    // The weights of integrate_spectrum: h at the interior nodes, h/2 at the ends.
    int n = int(std::lround((kSpectrumMaxNm - kSpectrumMinNm) / step_nm));
    double h = (kSpectrumMaxNm - kSpectrumMinNm) / n;
    const double* m = space.rgb_from_xyz_matrix_f64();
    for (int j = 0; j <= n; ++j) {
        double l = kSpectrumMinNm + j * h;
        double wl = (j == 0 || j == n ? 0.5 : 1.0) * h * space.illuminant(l);
        double xyz[3] = {wl * cie_x(l), wl * cie_y(l), wl * cie_z(l)};
        lambda_.push_back(l);
        u_.push_back((l - kCentreNm) / kHalfWidthNm);
        for (int a = 0; a < 3; ++a)
            w_[a].push_back(m[3 * a] * xyz[0] + m[3 * a + 1] * xyz[1] + m[3 * a + 2] * xyz[2]);
    }
}

void SigmoidFit::rgb(const std::array<double, 3>& c, double out[3], double jac[9]) const {
    const int n = int(u_.size());
    if (jac)
        sums_and_jacobian(n, u_.data(), w_[0].data(), w_[1].data(), w_[2].data(), c[0], c[1], c[2], out, jac);
    else
        sums(n, u_.data(), w_[0].data(), w_[1].data(), w_[2].data(), c[0], c[1], c[2], out);
}

void SigmoidFit::rgb(const RGBSigmoidPolynomial& p, double out[3]) const {
    out[0] = out[1] = out[2] = 0;
    for (std::size_t i = 0; i < lambda_.size(); ++i) {
        double s = p(float(lambda_[i]));
        for (int a = 0; a < 3; ++a) out[a] += s * w_[a][i];
    }
}

double SigmoidFit::residual(const std::array<double, 3>& c, const double target[3], double r[3],
                            double jac[9], double& rgb_error) const {
    double v[3];
    rgb(c, v, jac);
    rgb_error =
        std::max({std::abs(v[0] - target[0]), std::abs(v[1] - target[1]), std::abs(v[2] - target[2])});
    if (mode_ == FitResidual::rgb) {
        for (int a = 0; a < 3; ++a) r[a] = v[a] - target[a];
        return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    }
    // CIELAB: L = 116 f(Y/Yn) - 16, a = 500 (f(X/Xn) - f(Y/Yn)), b = 200 (f(Y/Yn) - f(Z/Zn)), and the chain
    // rule through XYZ = M_xyz←rgb rgb for the Jacobian.
    const double* m = space_.xyz_from_rgb_matrix_f64();
    const double* white = space_.white_xyz();
    double lab[2][3], dlab[3][3] = {};
    for (int which = 0; which < 2; ++which) {
        const double* in = which == 0 ? v : target;
        double f[3], df[3];
        for (int a = 0; a < 3; ++a) {
            double xyz = m[3 * a] * in[0] + m[3 * a + 1] * in[1] + m[3 * a + 2] * in[2];
            lab_f(xyz / white[a], f[a], df[a]);
            df[a] /= white[a];
        }
        lab[which][0] = 116 * f[1] - 16;
        lab[which][1] = 500 * (f[0] - f[1]);
        lab[which][2] = 200 * (f[1] - f[2]);
        if (which == 0) { // ∂lab/∂xyz
            dlab[0][1] = 116 * df[1];
            dlab[1][0] = 500 * df[0], dlab[1][1] = -500 * df[1];
            dlab[2][1] = 200 * df[1], dlab[2][2] = -200 * df[2];
        }
    }
    for (int a = 0; a < 3; ++a) r[a] = lab[0][a] - lab[1][a];
    if (jac) {
        double d[9] = {}, out[9] = {}; // ∂lab/∂rgb = ∂lab/∂xyz · M, then · ∂rgb/∂c
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 3; ++k)
                for (int t = 0; t < 3; ++t) d[3 * a + k] += dlab[a][t] * m[3 * t + k];
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 3; ++k)
                for (int t = 0; t < 3; ++t) out[3 * a + k] += d[3 * a + t] * jac[3 * t + k];
        std::copy(out, out + 9, jac);
    }
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

SigmoidFit::Result SigmoidFit::solve(const std::array<double, 3>& target_rgb,
                                     const std::array<double, 3>& start, double tolerance, int max_iterations,
                                     double bound) const {
    auto bounded = [bound](std::array<double, 3> c) {
        double m = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
        if (m > bound)
            for (double& v : c) v *= bound / m;
        return c;
    };
    Result res;
    res.c = bounded(start);
    double r[3], J[9];
    double cost = residual(res.c, target_rgb.data(), r, J, res.rgb_error);
    double mu = 1e-6; // Marquardt's damping, relative to diag(JᵀJ)
    int slow = 0;     // consecutive iterations that lowered the cost by less than 1% (a stall)
    for (; res.iterations < max_iterations && res.rgb_error > tolerance && slow < 3; ++res.iterations) {
        double A[9] = {}, g[3] = {};
        for (int k = 0; k < 3; ++k) {
            for (int l = 0; l < 3; ++l)
                for (int a = 0; a < 3; ++a) A[3 * k + l] += J[3 * a + k] * J[3 * a + l];
            for (int a = 0; a < 3; ++a) g[k] -= J[3 * a + k] * r[a];
        }
        bool accepted = false;
        while (mu < 1e12) {
            double Ad[9];
            std::copy(A, A + 9, Ad);
            for (int k = 0; k < 3; ++k) Ad[4 * k] += mu * A[4 * k] + 1e-300;
            double step[3];
            if (solve3(Ad, g, step)) {
                std::array<double, 3> c =
                    bounded({res.c[0] + step[0], res.c[1] + step[1], res.c[2] + step[2]});
                double rn[3], Jn[9], en;
                double cn = residual(c, target_rgb.data(), rn, Jn, en);
                if (cn < cost) {
                    slow = cn > cost * 0.99 ? slow + 1 : 0;
                    res.c = c, cost = cn, res.rgb_error = en;
                    std::copy(rn, rn + 3, r);
                    std::copy(Jn, Jn + 9, J);
                    mu = std::max(mu / 4, 1e-9);
                    accepted = true;
                    break;
                }
            }
            mu = std::max(mu, 1e-9) * 8;
        }
        if (!accepted) break; // stalled: no step lowers the cost (an unreachable target's best fit)
    }
    return res;
}

SigmoidFit::Result SigmoidFit::refine(const std::array<double, 3>& target_rgb,
                                      const std::array<double, 3>& start, const SigmoidFit& coarse,
                                      double tolerance, int max_steps, double bound) const {
    auto error = [&](const std::array<double, 3>& c, double e[3]) {
        double v[3];
        rgb(c, v);
        for (int a = 0; a < 3; ++a) e[a] = v[a] - target_rgb[a];
        return std::max({std::abs(e[0]), std::abs(e[1]), std::abs(e[2])});
    };
    double J[9], v[3], e[3];
    coarse.rgb(start, v, J);
    Result res;
    res.c = start;
    res.rgb_error = error(start, e);
    for (; res.iterations < max_steps && res.rgb_error > tolerance; ++res.iterations) {
        double minus_e[3] = {-e[0], -e[1], -e[2]}, step[3];
        if (!solve3(J, minus_e, step)) break;
        std::array<double, 3> c = {res.c[0] + step[0], res.c[1] + step[1], res.c[2] + step[2]};
        if (std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])}) > bound) break;
        double en[3], err = error(c, en);
        if (!(err < res.rgb_error)) break;
        res.c = c, res.rgb_error = err;
        std::copy(en, en + 3, e);
    }
    return res;
}

RGBSigmoidPolynomial SigmoidFit::to_nm(const std::array<double, 3>& c) {
    // a ((λ - m)/w)² + b (λ - m)/w + c = (a/w²) λ² + (b/w - 2 a m / w²) λ + (a m²/w² - b m/w + c).
    constexpr double m = kCentreNm, w = kHalfWidthNm;
    return {float(c[0] / (w * w)), float(c[1] / w - 2 * c[0] * m / (w * w)),
            float(c[0] * m * m / (w * w) - c[1] * m / w + c[2])};
}

} // namespace illum

// Fitting one sigmoid polynomial to one RGB: the optimisation of Jakob & Hanika 2019 §4, run by the table
// generator (tools/rgb2spec_opt.cpp) for every entry of the uplifting tables.
//
// The spectrum s(λ) = S(c0 u² + c1 u + c2) reflects the space's illuminant I (Y-normalised); its colour is
//   rgb(c) = M_rgb←xyz ∫ s(λ) I(λ) (x̄, ȳ, z̄)(λ) dλ          (integrate_spectrum's grid)
// and Levenberg-Marquardt drives the residual to zero, either rgb(c) - target (the default, which is what
// the round trip measures) or, as the paper does, the difference in CIELAB (CIE 15:2004 §8.2.1, white =
// the illuminant). The two differ only for targets out of reach; measured on sRGB's tables the round
// trip's largest errors are the same to 3 digits but for [0, 1]³, 0.0221 (RGB) against 0.0233 (CIELAB). The
// Jacobian is analytic: ∂s/∂c_k = S'(x) u^(2-k), S'(x) = 1 / (2 (1+x²)^(3/2)). The fit works in the
// normalised wavelength u = (λ - 595 nm) / 235 nm ∈ [-1, 1], where the three coefficients are of similar size
// (the paper also normalises λ); to_nm() converts for the runtime tables.
#pragma once

#include <array>
#include <vector>

#include "illum/radiometry/color_space.h"

namespace illum {

enum class FitResidual { rgb, lab };

class SigmoidFit {
public:
    static constexpr double kCentreNm = 595, kHalfWidthNm = 235;

    explicit SigmoidFit(const RGBColorSpace& space, FitResidual residual = FitResidual::rgb,
                        double step_nm = kSpectralStepNm);

    struct Result {
        std::array<double, 3> c{}; // normalised-wavelength coefficients
        double rgb_error = 0;      // max |rgb(c) - target|
        int iterations = 0;
    };
    // Levenberg-Marquardt (damping μ diag(JᵀJ), μ / 4 after a step that lowers the cost, x 8 until one
    // does) from `start`; stops when the RGB error is below `tolerance`, after max_iterations, or when
    // three steps in a row lower the cost by less than 1% (a target out of reach). Every step is scaled
    // back into max |c_k| <= bound (see kBound).
    Result solve(const std::array<double, 3>& target_rgb, const std::array<double, 3>& start,
                 double tolerance = 1e-7, int max_iterations = 100, double bound = kBound) const;

    // The bound on the normalised coefficients. A target outside the colours the sigmoid polynomials
    // reach (a wide gamut's saturated corners, which no reflectance has, or the darkest saturated colours)
    // drives them to infinity: ever sharper steps, different from one entry to the next, whose trilinear
    // interpolation is meaningless. Scaling c back (x(u) keeps its zeros, only its steepness is limited)
    // keeps neighbouring entries alike. S(±200) is within 6.3e-6 of 1 and 0, so greys lose nothing; a
    // step at |∂x/∂u| <= 400 spans about 4 nm.
    static constexpr double kBound = 200;

    // Newton steps on this grid with the Jacobian of `coarse` at `start` held fixed (the chord method): from
    // a solution on a coarser grid each step costs one evaluation without derivatives. Steps that do not
    // lower the RGB error are not taken.
    Result refine(const std::array<double, 3>& target_rgb, const std::array<double, 3>& start,
                  const SigmoidFit& coarse, double tolerance = 1e-7, int max_steps = 4,
                  double bound = kBound) const;

    // rgb(c) and, if jac is given, ∂rgb/∂c (row-major, jac[3 a + k] = ∂rgb_a/∂c_k).
    void rgb(const std::array<double, 3>& c, double out[3], double jac[9] = nullptr) const;

    // The RGB of a runtime polynomial (float, λ in nm) by the same quadrature, for checks.
    void rgb(const RGBSigmoidPolynomial& p, double out[3]) const;

    // a u² + b u + c with u = (λ - 595) / 235, as a polynomial in λ [nm].
    static RGBSigmoidPolynomial to_nm(const std::array<double, 3>& c);

private:
    // The residual in the chosen space and its Jacobian; returns the squared norm, and the max RGB error.
    double residual(const std::array<double, 3>& c, const double target[3], double r[3], double jac[9],
                    double& rgb_error) const;

    const RGBColorSpace& space_;
    FitResidual mode_;
    // The grid's wavelengths, normalised wavelengths u, and rgb weights h I M·(x̄, ȳ, z̄) (h/2 at the ends).
    std::vector<double> lambda_, u_, w_[3];
};

} // namespace illum

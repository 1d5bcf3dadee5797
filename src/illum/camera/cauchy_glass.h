// A glass's index of refraction as a function of wavelength from its catalogue pair (n_d, V_d), by
// Cauchy's two-term dispersion formula (A. L. Cauchy, "Mémoire sur la dispersion de la lumière", 1836):
//
//     n(λ) = A + B / λ²,
//
// with A and B fitted through the two catalogue conditions
//
//     n(λ_d) = n_d                          λ_d = 587.56 nm (He d line)
//     n(λ_F) - n(λ_C) = (n_d - 1) / V_d     λ_F = 486.13 nm (H F line), λ_C = 656.27 nm (H C line),
//
// the second being the definition of the Abbe number V_d = (n_d - 1) / (n_F - n_C) (ISO 7944; Schott,
// TIE-29 "Refractive index and dispersion", 2016). So B = (n_d - 1) / (V_d (λ_F⁻² - λ_C⁻²)) and
// A = n_d - B / λ_d². Two terms reproduce a catalogue glass to a few 1e-4 over the visible, the accuracy
// the pair (n_d, V_d) carries anyway (the partial dispersions a Sellmeier fit would need are not given).
// V_d = 0 means no dispersion: n(λ) = n_d.
#pragma once

namespace illum {

inline constexpr double kLambdaF = 486.13, kLambdaD = 587.56, kLambdaC = 656.27; // nm

struct CauchyGlass {
    double a = 1, b = 0; // n(λ) = a + b / λ², λ in µm

    static CauchyGlass from_abbe(double n_d, double v_d) {
        auto inv2 = [](double nm) { return 1.0 / ((nm * 1e-3) * (nm * 1e-3)); };
        CauchyGlass g;
        g.b = v_d > 0 ? (n_d - 1) / (v_d * (inv2(kLambdaF) - inv2(kLambdaC))) : 0;
        g.a = n_d - g.b * inv2(kLambdaD);
        return g;
    }
    double index(double lambda_nm) const {
        double um = lambda_nm * 1e-3;
        return a + b / (um * um);
    }
};

} // namespace illum

// Fitting (analysis/brdf_fit.h, levenberg_marquardt.h): Levenberg-Marquardt on a problem with a known
// answer; the roughness of GGX and Beckmann tables made from the analytic models themselves, written and
// read back as MERL files, recovered within 2%; the same from the registry's rough conductor; and the
// error of fits between models, reported.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "illum/analysis/brdf_fit.h"
#include "illum/analysis/levenberg_marquardt.h"
#include "illum/bsdf/registry.h"

namespace illum {
namespace {

// y = a exp(-b t) + c from exact data: LM finds (a, b, c) from a poor start; bounds hold.
TEST(LevenbergMarquardt, RecoversAnExponentialDecay) {
    std::vector<double> t, y;
    for (int i = 0; i < 40; ++i) {
        t.push_back(0.1 * i);
        y.push_back(2.5 * std::exp(-1.3 * t.back()) + 0.4);
    }
    LeastSquaresProblem p;
    p.residuals = [&](const std::vector<double>& x, std::vector<double>& r) {
        r.resize(t.size());
        for (std::size_t k = 0; k < t.size(); ++k) r[k] = x[0] * std::exp(-x[1] * t[k]) + x[2] - y[k];
    };
    p.lower = {0, 0, -10};
    p.upper = {10, 10, 10};
    p.step = {1e-6, 1e-6, 1e-6};
    LeastSquaresResult r = levenberg_marquardt(p, {1, 5, 0});
    EXPECT_TRUE(r.converged) << r.stop;
    EXPECT_NEAR(r.x[0], 2.5, 1e-5);
    EXPECT_NEAR(r.x[1], 1.3, 1e-5);
    EXPECT_NEAR(r.x[2], 0.4, 1e-5);
    // A bound that cuts the minimum off: the fit stops on it.
    p.upper[1] = 1.0;
    r = levenberg_marquardt(p, {1, 0.5, 0});
    EXPECT_DOUBLE_EQ(r.x[1], 1.0);
}

TEST(LevenbergMarquardt, CholeskySolve) {
    std::vector<double> x;
    ASSERT_TRUE(cholesky_solve({4, 2, 2, 3}, {2, 1}, 2, &x));
    EXPECT_NEAR(x[0], 0.5, 1e-12);
    EXPECT_NEAR(x[1], 0.0, 1e-12);
    EXPECT_FALSE(cholesky_solve({1, 2, 2, 1}, {1, 1}, 2, &x)) << "indefinite";
}

std::string temp_table(const std::string& name) {
    return (std::filesystem::path(::testing::TempDir()) / name).string();
}

// Tables made from the fitted form itself (ρd/π + ρs lobe, coloured), written as MERL files and read back.
TEST(BrdfFit, RecoversRoughnessOfSyntheticMerlTables) {
    for (FitFamily family : {FitFamily::GGX, FitFamily::Beckmann}) {
        for (double alpha : {0.05, 0.2, 0.5}) {
            FitParameters truth;
            truth.family = family;
            truth.rho_d = {0.10, 0.20, 0.05};
            truth.rho_s = {0.60, 0.50, 0.40};
            truth.alpha = alpha;
            std::string path = temp_table(std::string(to_string(family)) + "_fit.binary");
            MerlTable::from_bxdf(*make_fitted_bxdf(truth)).write(path);
            BrdfSamples s = samples_from_merl(MerlTable::read(path));
            FitResult r = fit_brdf(s, family);
            double rel = std::abs(r.params.alpha / alpha - 1);
            std::printf(
                "%-8s α = %.3f: fitted α = %.6f (%.2e relative), ρd %.4f %.4f %.4f, ρs %.4f %.4f %.4f, "
                "log-RMS %.2e, %d iterations (%s)\n",
                to_string(family), alpha, r.params.alpha, rel, r.params.rho_d[0], r.params.rho_d[1],
                r.params.rho_d[2], r.params.rho_s[0], r.params.rho_s[1], r.params.rho_s[2], r.error.log_rms,
                r.iterations, r.stop.c_str());
            EXPECT_LT(rel, 0.02) << to_string(family) << " α " << alpha;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(r.params.rho_d[c], truth.rho_d[c], 0.02 * truth.rho_s[c]);
                EXPECT_NEAR(r.params.rho_s[c], truth.rho_s[c], 0.02 * truth.rho_s[c]);
            }
            EXPECT_LT(r.error.relative_rms, 1e-3);
        }
    }
}

// The registry's rough conductor with F ≈ 1 (η = 1, k = 100: F0 = 0.9996), as `illum brdf fit --from` sees
// it.
TEST(BrdfFit, RecoversRoughnessOfTheRegistryRoughConductor) {
    for (const char* distribution : {"ggx", "beckmann"}) {
        auto bxdf = make_bxdf("rough-conductor",
                              {{"alpha", "0.3"}, {"distribution", distribution}, {"eta", "1"}, {"k", "100"}});
        FitResult r = fit_brdf(samples_from_bxdf(*bxdf), *fit_family_from_string(distribution));
        std::printf("rough-conductor %s α = 0.3: fitted α = %.5f, ρs %.4f, ρd %.4f, log-RMS %.2e\n",
                    distribution, r.params.alpha, r.params.rho_s[1], r.params.rho_d[1], r.error.log_rms);
        EXPECT_NEAR(r.params.alpha, 0.3, 0.02 * 0.3) << distribution;
        EXPECT_NEAR(r.params.rho_s[1], 1.0, 0.01);
    }
}

// Fits between models: each family fitted to the others' values; a family fitted to its own values has
// (nearly) no error, the others a measurable one.
TEST(BrdfFit, ReportsTheErrorOfFitsBetweenModels) {
    struct Source {
        const char* name;
        FitFamily family;
    };
    FitParameters base;
    base.rho_d = {0.05, 0.05, 0.05};
    base.rho_s = {0.8, 0.8, 0.8};
    base.alpha = 0.25;
    base.f0 = 1;
    std::printf("%-14s %-14s %8s %10s %10s %5s\n", "source", "fitted", "α/m", "log-RMS", "rel. RMS", "iter");
    for (FitFamily source : {FitFamily::GGX, FitFamily::Beckmann, FitFamily::Ward}) {
        FitParameters truth = base;
        truth.family = source;
        BrdfSamples s = samples_from_bxdf(*make_fitted_bxdf(truth));
        double self = 0, errors[4] = {};
        for (FitFamily fitted :
             {FitFamily::GGX, FitFamily::Beckmann, FitFamily::Ward, FitFamily::CookTorrance}) {
            FitResult r = fit_brdf(s, fitted);
            std::printf("%-14s %-14s %8.4f %10.3e %10.3e %5d\n", to_string(source), to_string(fitted),
                        r.params.alpha, r.error.log_rms, r.error.relative_rms, r.iterations);
            errors[int(fitted)] = r.error.log_rms;
            EXPECT_TRUE(std::isfinite(r.error.log_rms));
            if (fitted == source) {
                self = r.error.log_rms;
                EXPECT_LT(r.error.relative_rms, 1e-3);
            }
        }
        for (FitFamily fitted : {FitFamily::GGX, FitFamily::Beckmann, FitFamily::Ward}) {
            if (fitted != source) {
                EXPECT_GT(errors[int(fitted)], 10 * self + 1e-5)
                    << to_string(fitted) << " to " << to_string(source);
            }
        }
    }
}

TEST(BrdfFit, FamilyNames) {
    for (const char* n : {"ggx", "beckmann", "ward", "cook-torrance"})
        EXPECT_STREQ(to_string(*fit_family_from_string(n)), n);
    EXPECT_FALSE(fit_family_from_string("phong"));
}

} // namespace
} // namespace illum

// The lobe plots (analysis/lobe.h, brdf_plot.h) for every registered model: the figure is well-formed SVG,
// and the plotted lobe's integral, ∫ f(ω, wi) |cos θ_ω| dω over the plot's own grid plus its delta spikes,
// is the directional albedo `illum brdf albedo` computes for the same model (its quadrature of f, and
// its Monte Carlo estimate with the model's sampling), within 1%.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "illum/analysis/brdf_plot.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/registry.h"
#include "illum/image/svg.h"
#include "xml_check.h"

namespace illum {
namespace {

// A model with the parameters of its first audit case (merl needs a file: the audit's synthetic table).
std::unique_ptr<BxDF> first_case(const ModelSpec& m, std::string* label) {
    const auto& params = m.audit_grid.empty() ? std::map<std::string, std::string>{} : m.audit_grid[0].params;
    ParamValues v = resolve_params(m, params);
    *label = m.name + " " + v.describe();
    return m.make(v);
}

TEST(LobePlot, EveryModelGivesWellFormedSvg) {
    for (const ModelSpec& m : bxdf_models()) {
        std::string label;
        auto bxdf = first_case(m, &label);
        std::vector<BrdfPlotData> data = {brdf_plot_data(*bxdf, label, 30, 0)};
        std::string svg = to_svg(brdf_figure(data));
        test::XmlCheck x = test::check_xml(svg);
        EXPECT_TRUE(x.ok) << m.name << ": " << x.error;
        EXPECT_EQ(x.root, "svg") << m.name;
        int polylines = 0;
        for (const auto& e : x.elements) polylines += e == "polyline" || e == "polygon";
        EXPECT_GT(polylines, 10) << m.name;
        // And overlaid with Lambert (`illum brdf compare`).
        auto lambert = make_bxdf("lambert", {});
        data.push_back(brdf_plot_data(*lambert, "lambert", 30, 0));
        x = test::check_xml(to_svg(brdf_figure(data)));
        EXPECT_TRUE(x.ok) << m.name << " vs lambert: " << x.error;
    }
}

TEST(LobePlot, IntegralOfThePlottedLobeIsTheAlbedo) {
    std::printf("%-22s %5s  %-9s %-9s %-7s  %-9s %-18s %-7s\n", "model", "θi", "plot ∫f", "quad", "diff",
                "plot all", "MC ± σ", "diff");
    for (const ModelSpec& m : bxdf_models()) {
        std::string label;
        auto bxdf = first_case(m, &label);
        for (double theta : {0.0, 30.0, 60.0, 80.0}) {
            Vector3f wi = direction_deg(theta, 0);
            LobeGrid lobe = sample_lobe(*bxdf, wi);
            // What `illum brdf albedo MODEL --theta θ --samples 100000 --quad 256` computes.
            AlbedoEstimate e = directional_albedo(*bxdf, wi, m.delta, 256, 100000, 1);
            Rgb64 of_f = lobe.integral_of_f(), all = lobe.albedo();
            double worst_q = 0, worst_mc = 0;
            for (int c = 0; c < 3; ++c) {
                if (e.has_quadrature) {
                    double d = std::abs(of_f[c] - e.quadrature[c]);
                    worst_q = std::max(worst_q, d / std::max(e.quadrature[c], 1e-3));
                    EXPECT_LE(d, 0.01 * e.quadrature[c] + 1e-4)
                        << m.name << " θi " << theta << " channel " << c << ": plotted ∫f " << of_f[c]
                        << ", quadrature " << e.quadrature[c];
                }
                double d = std::abs(all[c] - e.mc[c]);
                worst_mc = std::max(worst_mc, d / std::max(e.mc[c], 1e-3));
                EXPECT_LE(d, 0.01 * e.mc[c] + 4 * e.mc_stderr[c] + 1e-4)
                    << m.name << " θi " << theta << " channel " << c << ": plotted albedo " << all[c]
                    << ", MC " << e.mc[c] << " ± " << e.mc_stderr[c];
            }
            std::printf("%-22s %5g  %-9.5f %-9s %-7s  %-9.5f %.5f ± %.5f %+.2f%%\n", m.name.c_str(), theta,
                        channel_mean(of_f),
                        e.has_quadrature ? fmt::format("{:.5f}", channel_mean(e.quadrature)).c_str() : "-",
                        e.has_quadrature ? fmt::format("{:+.2f}%", 100 * worst_q).c_str() : "-",
                        channel_mean(all), channel_mean(e.mc), channel_mean(e.mc_stderr), 100 * worst_mc);
        }
    }
}

// The albedo curve is the integral of each θi's lobe grid, and the curve point at the plot's θi is the
// integral of the grid the 3D panel draws.
TEST(LobePlot, AlbedoCurveIsTheIntegralOfTheGrids) {
    auto bxdf = make_bxdf("rough-conductor", {{"alpha", "0.3"}});
    BrdfPlotData d = brdf_plot_data(*bxdf, "rc", 40, 0, {0, 40, 80});
    ASSERT_EQ(d.albedo.size(), 3u);
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(d.albedo[1].albedo[c], d.lobe.albedo()[c]);
    EXPECT_TRUE(d.lobe.spikes.empty());
}

// Delta models: the lobe is spikes, carrying the Fresnel split of smooth glass.
TEST(LobePlot, SpikesOfSmoothModels) {
    auto mirror = make_bxdf("mirror", {{"reflectance", "0.7"}});
    LobeGrid g = sample_lobe(*mirror, direction_deg(30, 0));
    ASSERT_EQ(g.spikes.size(), 1u);
    EXPECT_NEAR(g.spikes[0].share[0], 0.7, 1e-6);
    EXPECT_NEAR(g.spikes[0].direction.x, -0.5f, 1e-5f);
    auto glass = make_bxdf("dielectric", {{"eta", "1.5"}});
    g = sample_lobe(*glass, direction_deg(0, 0));
    ASSERT_EQ(g.spikes.size(), 2u);
    double r = std::min(g.spikes[0].share[0], g.spikes[1].share[0]);
    EXPECT_NEAR(r, 0.04, 1e-3) << "normal-incidence Fresnel reflectance ((η - 1)/(η + 1))²";
    EXPECT_NEAR(g.albedo()[0], 1.0, 1e-6);
}

} // namespace
} // namespace illum

// `illum brdf plot` and `illum brdf compare`: one figure of three panels per set of models, for light
// arriving from wi (lobe.h defines what is drawn):
//   1. the lobe I(ψ) = f |cos| in the plane of incidence, as a polar plot (delta lobes as arrows);
//   2. the lobe over the sphere as a wire mesh, the surface r = I(ω) ω in an axonometric view
//      (azimuth -60°, elevation 25°), from the same grid whose integral is the albedo;
//   3. the directional albedo ρ(θi) = ∫ I dω against θi, each point the integral of that θi's grid.
// Several models are overlaid in the palette's colours. Values are the mean of R, G and B; the data
// (RGB) can be written as JSON beside the figure.
#pragma once

#include <string>
#include <vector>

#include "illum/analysis/lobe.h"
#include "illum/image/drawing.h"

namespace illum {

struct BrdfPlotData {
    std::string label; // "model name=value ..."
    double theta_i_deg = 0, phi_i_deg = 0;
    LobeGrid lobe;
    std::vector<PlaneSample> plane;
    std::vector<AlbedoPoint> albedo;
};

// θi of the albedo curve: 0° to 88° in steps of 4°.
std::vector<double> default_albedo_thetas();

BrdfPlotData brdf_plot_data(const BxDF& bxdf, std::string label, double theta_i_deg, double phi_i_deg,
                            const std::vector<double>& albedo_thetas_deg = default_albedo_thetas(),
                            const LobeOptions& options = {});

Drawing brdf_figure(const std::vector<BrdfPlotData>& models);

// {"models": [{"label", "theta_i", "phi_i", "albedo_at_wi": [r,g,b], "albedo_of_f_at_wi", "spikes": [...],
//   "plane": [[ψ, r, g, b], ...], "albedo": [[θi, r, g, b], ...], "albedo_of_f": [...]}]}
std::string brdf_plot_json(const std::vector<BrdfPlotData>& models);

} // namespace illum

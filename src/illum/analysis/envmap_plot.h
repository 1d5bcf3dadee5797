// `illum envmap show`: an environment map and its irradiance side by side, in latitude-longitude layout:
// the radiance L, the order-2 spherical-harmonic irradiance of Ramamoorthi & Hanrahan 2001 (E_SH(n) =
// Σ Â_l L_lm Y_lm(n)) and the brute-force irradiance E(n) = Σ L max(0, n·ω) Ω (envmap/irradiance.h). The
// irradiances are shown as E/π, the radiance a white Lambertian surface facing n would have, so all
// three panels share one exposure and one unit. The caption gives the SH irradiance's mean difference
// from the brute force.
#pragma once

#include <string>

#include "illum/envmap/spherical_harmonics.h"
#include "illum/image/drawing.h"

namespace illum {

struct EnvmapFigureOptions {
    int panel_height = 180;      // texels of each latlong panel (its width is twice that)
    int brute_force_height = 64; // the brute-force irradiance's resolution (and its input's)
    bool auto_exposure = true;   // mean of E/π to 0.5 before the ACES tone map
    float exposure_stops = 0;    // added to the automatic exposure (or the exposure when it is off)
};

struct EnvmapFigure {
    Drawing drawing;
    SH9 sh;
    double exposure_scale = 1;
    // Solid-angle weighted mean |E_SH - E| over mean E, on the brute force's grid.
    double sh_mean_difference = 0;
};

EnvmapFigure envmap_figure(const EnvironmentMap& map, const std::string& label,
                           const EnvmapFigureOptions& options = {});

} // namespace illum

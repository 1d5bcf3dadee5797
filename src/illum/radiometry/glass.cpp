#include "illum/radiometry/glass.h"

#include <array>
#include <cmath>

namespace illum {

double sellmeier_index(double lambda_nm, const double B[3], const double C[3]) {
    double l2 = lambda_nm * lambda_nm * 1e-6; // λ² in µm²
    double n2 = 1;
    for (int i = 0; i < 3; ++i) n2 += B[i] * l2 / (l2 - C[i]);
    return std::sqrt(n2);
}

double cauchy_index(double lambda_nm, double A, double B) {
    double l_um = lambda_nm * 1e-3;
    return A + B / (l_um * l_um);
}

namespace {

// Sellmeier coefficients B1, B2, B3 and C1, C2, C3 [µm²] of the SCHOTT optical glass catalogue
// (Zemax catalogue schott_2017-01-20b.agf and SCHOTT data sheets, as listed by refractiveindex.info,
// database/data/specs/schott/optical/<glass>.yml), with the catalogue's wavelength range.
// Columns: pbrt-v4 name, Schott name, {B1, B2, B3}, {C1, C2, C3}, range [nm].
// clang-format off
const std::array<SchottGlass, 7> kGlasses = {{
    {"glass-BK7", "N-BK7", {1.03961212, 0.231792344, 1.01046945},
     {0.00600069867, 0.0200179144, 103.560653}, 300, 2500},
    {"glass-BAF10", "N-BAF10", {1.5851495, 0.143559385, 1.08521269},
     {0.00926681282, 0.0424489805, 105.613573}, 350, 2500},
    {"glass-FK51A", "N-FK51A", {0.971247817, 0.216901417, 0.904651666},
     {0.00472301995, 0.0153575612, 168.68133}, 290, 2500},
    {"glass-LASF9", "N-LASF9", {2.00029547, 0.298926886, 1.80691843},
     {0.0121426017, 0.0538736236, 156.530829}, 365, 2500},
    {"glass-F5", "N-SF5", {1.52481889, 0.187085527, 1.42729015},
     {0.011254756, 0.0588995392, 129.141675}, 370, 2500},
    {"glass-F10", "N-SF10", {1.62153902, 0.256287842, 1.64447552},
     {0.0122241457, 0.0595736775, 147.468793}, 380, 2500},
    {"glass-F11", "N-SF11", {1.73759695, 0.313747346, 1.89878101},
     {0.013188707, 0.0623068142, 155.23629}, 370, 2500},
}};
// clang-format on

} // namespace

std::span<const SchottGlass> schott_glasses() { return kGlasses; }

const SchottGlass* schott_glass(std::string_view pbrt_name) {
    for (const SchottGlass& g : kGlasses)
        if (g.pbrt_name == pbrt_name) return &g;
    return nullptr;
}

} // namespace illum

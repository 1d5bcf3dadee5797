// Measured scattering coefficients of real materials, by pbrt-v4's preset names (a medium's "preset", a
// subsurface material's "name"): Jensen et al. 2001, "A Practical Model for Subsurface Light Transport"
// (skin, marble, milk, ketchup...), and Narasimhan et al. 2006, "Acquiring Scattering Properties of
// Participating Media by Dilution" (milks, coffees, wines, juices...).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "illum/radiometry/color.h"

namespace illum {

struct MeasuredMedium {
    Color3 sigma_a, sigma_s; // [mm^-1], as the papers give them and pbrt-v4 uses them
};

std::optional<MeasuredMedium> measured_medium(std::string_view name);
const std::vector<std::string>& measured_medium_names();

} // namespace illum

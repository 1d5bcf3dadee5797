// PROVISIONAL (replaced at merge by the spectra branch): pbrt-v4's named spectra as full spectra.
#pragma once

#include <optional>
#include <string_view>

#include "illum/radiometry/spectra.h"

namespace illum {

std::optional<PiecewiseLinearSpectrum> named_spectrum(std::string_view name);

} // namespace illum

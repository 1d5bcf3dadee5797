#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

VisibleWavelengthTable::VisibleWavelengthTable() {
    for (int i = 0; i <= kVisibleBins; ++i) {
        double u = double(i) / kVisibleBins;
        // The analytic inverse CDF in double, clamped to the range it maps [0, 1] onto.
        double l = 538 - 138.888889 * std::atanh(0.85691062 - 1.82750197 * u);
        lambda[i] = float(std::clamp(l, double(kVisibleMin), double(kVisibleMax)));
    }
    for (int i = 0; i < kVisibleBins; ++i)
        pdf[i] = float(1.0 / (kVisibleBins * double(lambda[i + 1] - lambda[i])));
}

const VisibleWavelengthTable& visible_wavelength_table() {
    static const VisibleWavelengthTable table;
    return table;
}

} // namespace illum

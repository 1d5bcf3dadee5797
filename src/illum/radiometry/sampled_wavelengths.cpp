#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

VisibleWavelengthTable::VisibleWavelengthTable() {
    for (int i = 0; i <= kVisibleBins; ++i) {
        // The analytic inverse CDF, clamped to the range it maps [0, 1] onto.
        double l = sample_visible_wavelength(double(i) / kVisibleBins);
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

// PROVISIONAL (replaced at merge by the spectra branch).
#include "illum/radiometry/named_spectra.h"

#include "illum/radiometry/metal_spectra.h"

namespace illum {

std::optional<PiecewiseLinearSpectrum> named_spectrum(std::string_view name) {
    if (name.rfind("metal-", 0) == 0) {
        std::string_view rest = name.substr(6);
        bool eta = rest.ends_with("-eta"), k = rest.ends_with("-k");
        if (!eta && !k) return std::nullopt;
        const MeasuredIndex* m = measured_index(rest.substr(0, rest.size() - (eta ? 4 : 2)));
        if (!m) return std::nullopt;
        return eta ? m->eta : m->k;
    }
    return std::nullopt;
}

} // namespace illum

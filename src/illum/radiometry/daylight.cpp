// PROVISIONAL (replaced at merge by the spectra branch): a blackbody stand-in.
#include "illum/radiometry/daylight.h"

#include "illum/radiometry/spectra.h"

namespace illum {

double cie_daylight(double lambda_nm, double cct_kelvin) { return blackbody(lambda_nm, cct_kelvin); }

} // namespace illum

// PROVISIONAL (replaced at merge by the spectra branch).
#pragma once

namespace illum {

double cie_daylight(double lambda_nm, double cct_kelvin);

} // namespace illum

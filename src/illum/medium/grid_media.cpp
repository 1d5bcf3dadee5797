// TEMPORARY placeholder until the grid media land (uniformgrid, rgbgrid, cloud, nanovdb).
#include "illum/medium/create_medium.h"

namespace illum {

CreatedMedium create_grid_medium(const MediumDesc&, Diagnostics&) { return {}; }

} // namespace illum

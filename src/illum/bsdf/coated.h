// pbrt-v4's coated materials as layered models (layered.h): a dielectric coat, smooth or rough, over a
// Lambertian base (coated-diffuse) or a conductor base, smooth or rough (coated-conductor).
#pragma once

#include "illum/bsdf/lambert.h"
#include "illum/bsdf/layered.h"

namespace illum {

using CoatedDiffuseBxDF = LayeredBxDF<LambertBxDF>;
using CoatedConductorBxDF = LayeredBxDF<ConductorInterface>;

} // namespace illum

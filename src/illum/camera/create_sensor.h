// The film's sensor from the scene: pbrt-v4's "sensor" (only its default "cie1931", the CIE matching
// functions; a named camera's measured curves are an error), "iso" (100) and "whitebalance" (0: none), and
// the exposure time, the camera's "shutterclose" - "shutteropen" (1). The imaging ratio is
// exposure time · ISO / 100, as in pbrt-v4; the film's "maxcomponentvalue" limits each sample
// (Sensor::to_film).
#pragma once

#include "illum/camera/sensor.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

Sensor create_sensor(const EntityDesc& film, const EntityDesc& camera, const RGBColorSpace& output,
                     Diagnostics& diag);

} // namespace illum

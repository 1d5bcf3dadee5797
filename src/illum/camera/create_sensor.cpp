#include "illum/camera/create_sensor.h"

#include <fmt/format.h>
#include <limits>

namespace illum {

Sensor create_sensor(const EntityDesc& film, const EntityDesc& camera, const RGBColorSpace& output,
                     Diagnostics&) {
    std::string sensor = film.params.get_string("sensor", "cie1931");
    if (sensor != "cie1931")
        throw Error(
            film.params.find("sensor")->loc,
            fmt::format("unknown sensor \"{}\": only \"cie1931\" is available (pbrt-v4's measured camera "
                        "curves are not included)",
                        sensor));
    float iso = film.params.get_float("iso", 100);
    float white_balance = film.params.get_float("whitebalance", 0);
    float exposure = camera.params.get_float("shutterclose", 1) - camera.params.get_float("shutteropen", 0);
    if (!(iso > 0) || !std::isfinite(iso))
        throw Error(film.params.find("iso")->loc, "\"iso\" must be positive");
    if (!(white_balance >= 0) || !std::isfinite(white_balance) || (white_balance > 0 && white_balance < 1000))
        throw Error(film.params.find("whitebalance")->loc,
                    "\"whitebalance\" must be 0 (none) or a temperature of at least 1000 K");
    if (!(exposure > 0) || !std::isfinite(exposure))
        throw Error(camera.loc, "the exposure time (shutterclose - shutteropen) must be positive");
    // The film's "maxcomponentvalue" (default +inf) limits each sample's sensor value (Sensor::to_film).
    float max_component = film.params.get_float("maxcomponentvalue", std::numeric_limits<float>::infinity());
    if (!(max_component > 0))
        throw Error(film.params.find("maxcomponentvalue")->loc, "\"maxcomponentvalue\" must be positive");
    Sensor s(output, exposure * iso / 100, white_balance);
    s.set_max_component_value(max_component);
    return s;
}

} // namespace illum

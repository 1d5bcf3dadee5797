// TEMPORARY placeholder until the measured data land.
#include "illum/medium/measured_media.h"

namespace illum {

std::optional<MeasuredMedium> measured_medium(std::string_view) { return std::nullopt; }
const std::vector<std::string>& measured_medium_names() {
    static const std::vector<std::string> names;
    return names;
}

} // namespace illum

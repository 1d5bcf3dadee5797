// Building a shape's parameters by hand, as the parser would give them (tests of geometry made without a
// scene file).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "illum/param/param_set.h"

namespace illum::test {

// A numeric parameter: name, values, and its declared type (float, point3, normal...).
inline Param floats(const std::string& name, std::vector<double> v, ParamType type = ParamType::Float) {
    Param p;
    p.name = name;
    p.type = type;
    p.numbers = std::move(v);
    return p;
}

} // namespace illum::test

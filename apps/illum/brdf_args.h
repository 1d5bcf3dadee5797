// The arguments the `illum brdf` subcommands share: name=value parameters, directions as θ,φ in degrees,
// comma-separated lists of numbers. Each throws illum::Error naming the option and the bad text.
#pragma once

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "illum/bsdf/albedo.h"
#include "illum/util/error.h"

namespace illum::cli {

inline std::map<std::string, std::string> parse_kv(const std::vector<std::string>& items) {
    std::map<std::string, std::string> out;
    for (const auto& s : items) {
        auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0) throw Error("--param expects name=value, got '" + s + "'");
        out[s.substr(0, eq)] = s.substr(eq + 1);
    }
    return out;
}

// "θ,φ" in degrees (φ optional, 0), θ in [0, 180].
inline std::pair<double, double> parse_theta_phi(const std::string& s, const char* what) {
    auto comma = s.find(',');
    try {
        std::size_t n1 = 0, n2 = 0;
        double t = std::stod(s.substr(0, comma), &n1);
        double p = comma == std::string::npos ? 0.0 : std::stod(s.substr(comma + 1), &n2);
        if (n1 != s.substr(0, comma).size() || (comma != std::string::npos && n2 != s.size() - comma - 1))
            throw std::invalid_argument("trailing");
        if (!(t >= 0 && t <= 180) || !std::isfinite(p)) throw std::invalid_argument("range");
        return {t, p};
    } catch (const std::exception&) {
        throw Error(std::string(what) + " expects θ,φ in degrees with θ in [0, 180], got '" + s + "'");
    }
}

inline Vector3f parse_angles(const std::string& s, const char* what) {
    auto [t, p] = parse_theta_phi(s, what);
    return direction_deg(t, p);
}

inline std::vector<double> parse_list(const std::string& s, const char* what) {
    std::vector<double> v;
    std::size_t start = 0;
    while (start <= s.size()) {
        auto p = s.find(',', start);
        std::string part = s.substr(start, p == std::string::npos ? std::string::npos : p - start);
        try {
            std::size_t n = 0;
            v.push_back(std::stod(part, &n));
            if (n != part.size()) throw std::invalid_argument("trailing");
        } catch (const std::exception&) {
            throw Error(std::string(what) + ": '" + part + "' is not a number");
        }
        if (p == std::string::npos) break;
        start = p + 1;
    }
    return v;
}

} // namespace illum::cli

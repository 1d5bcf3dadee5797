#include "illum/radiometry/named_spectra.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "illum/radiometry/cie_tables.h"
#include "illum/radiometry/conductor_rgb.h"
#include "illum/radiometry/daylight.h"
#include "illum/radiometry/glass.h"
#include "illum/radiometry/metal_spectra.h"

namespace illum {

namespace {

constexpr std::array<std::string_view, 37> kNames = {
    "glass-BK7",     "glass-BAF10",    "glass-FK51A",  "glass-LASF9",    "glass-F5",     "glass-F10",
    "glass-F11",     "metal-Ag-eta",   "metal-Ag-k",   "metal-Al-eta",   "metal-Al-k",   "metal-Au-eta",
    "metal-Au-k",    "metal-Cu-eta",   "metal-Cu-k",   "metal-CuZn-eta", "metal-CuZn-k", "metal-MgO-eta",
    "metal-MgO-k",   "metal-TiO2-eta", "metal-TiO2-k", "stdillum-A",     "stdillum-D50", "stdillum-D65",
    "stdillum-F1",   "stdillum-F2",    "stdillum-F3",  "stdillum-F4",    "stdillum-F5",  "stdillum-F6",
    "stdillum-F7",   "stdillum-F8",    "stdillum-F9",  "stdillum-F10",   "stdillum-F11", "stdillum-F12",
    "illum-acesD60",
};

enum class Kind { Glass, Metal, Illuminant };

struct Named {
    std::string_view name;
    Kind kind;
    PiecewiseLinearSpectrum spectrum;
};

template <class F>
PiecewiseLinearSpectrum sample(int first_nm, int last_nm, int step_nm, F f) {
    PiecewiseLinearSpectrum s;
    for (int l = first_nm; l <= last_nm; l += step_nm) {
        s.lambda.push_back(l);
        s.value.push_back(f(double(l)));
    }
    return s;
}

// pbrt-v4 scales its named illuminants to luminance 1 (PiecewiseLinearSpectrum::FromInterleaved).
PiecewiseLinearSpectrum unit_luminance(PiecewiseLinearSpectrum s) {
    double y = spectrum_to_xyz(s).y;
    for (double& v : s.value) v /= y;
    return s;
}

PiecewiseLinearSpectrum daylight_spectrum(double cct_kelvin) {
    return sample(cie::kDaylightFirstNm, cie::kDaylightLastNm, cie::kDaylightStepNm,
                  [&](double l) { return cie_daylight(l, cct_kelvin); });
}

PiecewiseLinearSpectrum fluorescent_spectrum(int lamp) {
    PiecewiseLinearSpectrum s;
    for (int i = 0; i < cie::kFluorescentCount; ++i) {
        s.lambda.push_back(cie::kFluorescentFirstNm + i * cie::kFluorescentStepNm);
        s.value.push_back(cie::kFluorescent[std::size_t(i)][std::size_t(lamp - 1)]);
    }
    return s;
}

PiecewiseLinearSpectrum illuminant(std::string_view name) {
    if (name == "stdillum-A") return sample(300, 830, 1, cie_illuminant_a);
    if (name == "stdillum-D50") return daylight_spectrum(daylight_cct_of_nominal(5000));
    if (name == "stdillum-D65")
        return sample(cie::kDaylightFirstNm, cie::kDaylightLastNm, cie::kDaylightStepNm, cie_d65);
    if (name == "illum-acesD60") return daylight_spectrum(6000);
    // "stdillum-F<n>"
    return fluorescent_spectrum(std::stoi(std::string(name.substr(10))));
}

std::vector<Named> build() {
    std::vector<Named> all;
    for (std::string_view name : kNames) {
        if (const SchottGlass* g = schott_glass(name)) {
            int first = int(std::ceil(std::max(360.0, g->min_nm)));
            all.push_back({name, Kind::Glass, sample(first, 830, 1, [g](double l) { return g->index(l); })});
        } else if (name.starts_with("metal-")) {
            bool eta = name.ends_with("-eta");
            std::string_view element = name.substr(6, name.size() - 6 - (eta ? 4 : 2));
            const MeasuredIndex* m = measured_index(element);
            all.push_back({name, Kind::Metal, eta ? m->eta : m->k});
        } else {
            all.push_back({name, Kind::Illuminant, unit_luminance(illuminant(name))});
        }
    }
    return all;
}

const Named* find(std::string_view name) {
    static const std::vector<Named> all = build();
    for (const Named& n : all)
        if (n.name == name) return &n;
    return nullptr;
}

} // namespace

std::optional<PiecewiseLinearSpectrum> named_spectrum(std::string_view name) {
    if (const Named* n = find(name)) return n->spectrum;
    return std::nullopt;
}

std::span<const std::string_view> named_spectrum_names() { return kNames; }

bool is_illuminant_name(const std::string& name) {
    const Named* n = find(name);
    return n && n->kind == Kind::Illuminant;
}

std::optional<Color3> named_spectrum_rgb(const std::string& name) {
    const Named* n = find(name);
    if (!n) return std::nullopt;
    switch (n->kind) {
    case Kind::Metal: {
        // The RGB index fitted to the measured spectra (conductor_rgb.h), not a reduction of η and k alone.
        std::string_view rest = std::string_view(name).substr(6);
        bool eta = rest.ends_with("-eta");
        const ConductorRgb* c = named_conductor_rgb(rest.substr(0, rest.size() - (eta ? 4 : 2)));
        return eta ? c->eta : c->k;
    }
    case Kind::Glass:
        return Color3(float(schott_glass(name)->index(550)));
    case Kind::Illuminant:
        return illuminant_spectrum_to_rgb(n->spectrum);
    }
    return std::nullopt;
}

} // namespace illum

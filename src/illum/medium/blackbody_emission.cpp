#include "illum/medium/blackbody_emission.h"

#include <cmath>
#include <vector>

#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

constexpr int kTableSize = 4096;
constexpr double kTableMin = 100, kTableMax = 1e6;

const std::vector<Color3>& table() {
    static const std::vector<Color3> t = [] {
        std::vector<Color3> v(kTableSize);
        for (int i = 0; i < kTableSize; ++i)
            v[std::size_t(i)] = blackbody_emission_rgb_exact(
                kTableMin * std::pow(kTableMax / kTableMin, double(i) / (kTableSize - 1)));
        return v;
    }();
    return t;
}

} // namespace

Color3 blackbody_emission_rgb_exact(double kelvin) {
    if (!(kelvin > 0)) return Color3(0.0f);
    Xyz c = spectrum_to_xyz([&](double l) { return blackbody_normalized(l, kelvin); });
    return blackbody_rgb(kelvin) * float(c.y);
}

std::size_t blackbody_table_bytes() { return kTableSize * sizeof(Color3); }

SampledSpectrum blackbody_emission(float kelvin, const SampledWavelengths& w) {
    if (!(kelvin > 100)) return SampledSpectrum(0.0f);
    if (w.spectral()) {
        SampledSpectrum s;
        for (int i = 0; i < kSpectrumSamples; ++i) s[i] = float(blackbody_normalized(w.lambda[i], kelvin));
        return s;
    }
    if (!(kelvin < kTableMax)) return SampledSpectrum(blackbody_emission_rgb_exact(kelvin));
    const std::vector<Color3>& t = table();
    double x = std::log(kelvin / kTableMin) / std::log(kTableMax / kTableMin) * (kTableSize - 1);
    int i = std::min(int(x), kTableSize - 2);
    float f = float(x - i);
    return SampledSpectrum(t[std::size_t(i)] * (1 - f) + t[std::size_t(i + 1)] * f);
}

} // namespace illum

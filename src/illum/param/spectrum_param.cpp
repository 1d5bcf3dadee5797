#include "illum/param/spectrum_param.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "illum/radiometry/spectra.h"

namespace illum {

Color3 spectrum_param_rgb(const Param& p, SpectrumKind kind) {
    p.used = true;
    if (p.strings.size() == 1 && p.strings[0] == "blackbody") {
        if (p.numbers.empty() || !(p.numbers[0] > 0))
            throw Error(p.loc, "blackbody needs a positive temperature");
        return blackbody_rgb(p.numbers[0]);
    }
    PiecewiseLinearSpectrum s;
    std::vector<double> v;
    if (p.strings.size() == 1 && p.numbers.empty()) {
        if (auto c = named_spectrum_rgb(p.strings[0])) {
            if (kind == SpectrumKind::Unbounded) return *c;
            float y = c->luminance(); // an illuminant is normalised to luminance 1, whatever its name
            if (!(y > 0)) throw Error(p.loc, fmt::format("spectrum \"{}\" has no luminance", p.strings[0]));
            return *c / y;
        }
        const std::string& file = p.strings[0];
        std::ifstream in(file);
        if (!in)
            throw Error(p.loc, fmt::format("unknown named spectrum or unreadable file \"{}\": {}", file,
                                           std::strerror(errno)));
        std::string line;
        while (std::getline(in, line)) {
            auto hash = line.find('#');
            if (hash != std::string::npos) line.resize(hash);
            std::istringstream ls(line);
            double x;
            while (ls >> x) v.push_back(x);
        }
        if (v.size() < 2 || v.size() % 2)
            throw Error(p.loc, fmt::format("spectrum file \"{}\" needs (wavelength, value) pairs", file));
    } else {
        if (p.numbers.size() < 2 || p.numbers.size() % 2)
            throw Error(p.loc, "a sampled spectrum needs (wavelength, value) pairs");
        v = p.numbers;
    }
    for (std::size_t i = 0; i < v.size(); i += 2) {
        s.lambda.push_back(v[i]);
        s.value.push_back(v[i + 1]);
    }
    for (std::size_t i = 1; i < s.lambda.size(); ++i)
        if (!(s.lambda[i] > s.lambda[i - 1])) throw Error(p.loc, "spectrum wavelengths must increase");
    return kind == SpectrumKind::Illuminant ? illuminant_spectrum_to_rgb(s) : unbounded_spectrum_to_rgb(s);
}

float spectrum_param_mean(const Param& p, Diagnostics* diag) {
    float mean = spectrum_param_rgb(p, SpectrumKind::Unbounded).average();
    bool named_glass = p.strings.size() == 1 && p.strings[0].rfind("glass-", 0) == 0;
    if (!named_glass && diag)
        diag->unsupported(
            p.loc, fmt::format("spectrally varying \"{}\" is rendered with its mean {:.4g}", p.name, mean));
    return mean;
}

} // namespace illum

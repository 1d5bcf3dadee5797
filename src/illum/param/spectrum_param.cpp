#include "illum/param/spectrum_param.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "illum/radiometry/glass.h"
#include "illum/radiometry/named_spectra.h"
#include "illum/radiometry/spectra.h"

namespace illum {

namespace {

// A spectrum parameter as the scene gives it: a blackbody temperature, or a table (named, inline or
// from a file). Throws illum::Error at its position for a bad spectrum or an unreadable file.
struct GivenSpectrum {
    double kelvin = 0; // > 0: a blackbody
    PiecewiseLinearSpectrum table;
    std::string name; // a named spectrum's name
};

GivenSpectrum given_spectrum(const Param& p) {
    p.used = true;
    GivenSpectrum g;
    if (p.strings.size() == 1 && p.strings[0] == "blackbody") {
        if (p.numbers.empty() || !(p.numbers[0] > 0))
            throw Error(p.loc, "blackbody needs a positive temperature");
        g.kelvin = p.numbers[0];
        return g;
    }
    // An index of refraction by its dispersion formula, tabulated at every nanometre of 360..830.
    if (p.strings.size() == 1 && (p.strings[0] == "sellmeier" || p.strings[0] == "cauchy")) {
        bool sellmeier = p.strings[0] == "sellmeier";
        if (p.numbers.size() != (sellmeier ? 6u : 2u))
            throw Error(p.loc, fmt::format("{} needs {} values", p.strings[0], sellmeier ? 6 : 2));
        for (double v : p.numbers)
            if (!std::isfinite(v)) throw Error(p.loc, fmt::format("{} values must be finite", p.strings[0]));
        for (int l = 360; l <= 830; ++l) {
            double n = sellmeier ? sellmeier_index(l, p.numbers.data(), p.numbers.data() + 3)
                                 : cauchy_index(l, p.numbers[0], p.numbers[1]);
            if (!(n > 0) || !std::isfinite(n))
                throw Error(p.loc, fmt::format("{} gives no real index at {} nm", p.strings[0], l));
            g.table.lambda.push_back(l);
            g.table.value.push_back(n);
        }
        return g;
    }
    std::vector<double> v;
    if (p.strings.size() == 1 && p.numbers.empty()) {
        if (auto named = named_spectrum(p.strings[0])) {
            g.table = std::move(*named);
            g.name = p.strings[0];
            return g;
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
        g.table.lambda.push_back(v[i]);
        g.table.value.push_back(v[i + 1]);
    }
    for (std::size_t i = 1; i < g.table.lambda.size(); ++i)
        if (!(g.table.lambda[i] > g.table.lambda[i - 1]))
            throw Error(p.loc, "spectrum wavelengths must increase");
    return g;
}

} // namespace

namespace {

// A spectrum outside the RGB gamut (a narrow band, say) has negative components; RGB mode renders its
// nearest non-negative colour (the negative components set to 0), warned by nothing: a scene that needs the
// colour exactly is rendered with --spectral.
Color3 in_gamut(Color3 c) { return {std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)}; }

Color3 reduce(const GivenSpectrum& g, const Param& p, SpectrumKind kind) {
    if (g.kelvin > 0) return blackbody_rgb(g.kelvin);
    if (!g.name.empty())
        if (auto c = named_spectrum_rgb(g.name)) {
            if (kind == SpectrumKind::Unbounded) return *c;
            float y = c->luminance(); // an illuminant is normalised to luminance 1, whatever its name
            if (!(y > 0)) throw Error(p.loc, fmt::format("spectrum \"{}\" has no luminance", g.name));
            return *c / y;
        }
    return kind == SpectrumKind::Illuminant ? illuminant_spectrum_to_rgb(g.table)
                                            : unbounded_spectrum_to_rgb(g.table);
}

std::shared_ptr<const DenselySampledSpectrum> tabulate(const GivenSpectrum& g, const Param& p,
                                                       SpectrumKind kind) {
    auto d = std::make_shared<DenselySampledSpectrum>(
        g.kelvin > 0 ? DenselySampledSpectrum::from([&](double l) { return blackbody(l, g.kelvin); })
                     : DenselySampledSpectrum::from([&](double l) { return g.table(l); }));
    if (kind == SpectrumKind::Illuminant) {
        // pbrt-v4's "scale /= SpectrumToPhotometric(s)": luminance ∫ s ȳ dλ = 1 (the film's Y of it).
        double y = 0;
        for (int i = 0; i < DenselySampledSpectrum::kCount; ++i)
            y += double(d->values()[std::size_t(i)]) * cie_y(DenselySampledSpectrum::kMin + i);
        if (!(y > 0)) throw Error(p.loc, fmt::format("spectrum \"{}\" has no luminance", p.name));
        d->scale(float(1 / y));
    }
    return d;
}

} // namespace

Color3 spectrum_param_rgb(const Param& p, SpectrumKind kind) {
    return in_gamut(reduce(given_spectrum(p), p, kind));
}

SpectrumParam spectrum_param(const Param& p, SpectrumKind kind) {
    GivenSpectrum g = given_spectrum(p);
    return {in_gamut(reduce(g, p, kind)), tabulate(g, p, kind)};
}

ScalarSpectrumParam spectrum_param_scalar(const Param& p, Diagnostics* diag) {
    SpectrumParam s = spectrum_param(p, SpectrumKind::Unbounded);
    float mean = s.rgb.average();
    // A named glass or a dispersion formula asks for dispersion, which spectral mode renders; any other
    // spectrum given for a scalar is worth a word about RGB mode.
    bool dispersive = p.strings.size() == 1 && (p.strings[0].rfind("glass-", 0) == 0 ||
                                                p.strings[0] == "sellmeier" || p.strings[0] == "cauchy");
    if (!dispersive && diag)
        diag->unsupported(
            p.loc, fmt::format("spectrally varying \"{}\" is rendered with its mean {:.4g} in RGB mode "
                               "(--spectral disperses it)",
                               p.name, mean));
    return {mean, std::move(s.spectrum)};
}

} // namespace illum

// A spectrum tabulated at every nanometre of the visible range, for spectra looked up at each path
// vertex in spectral mode (an emitter's radiance, a named metal's index): four table reads per lookup,
// whatever the spectrum was given as (samples, a file, a blackbody, an uplifted RGB).
#pragma once

#include <array>
#include <cmath>

#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

class DenselySampledSpectrum {
public:
    static constexpr int kMin = int(kVisibleMin), kMax = int(kVisibleMax), kCount = kMax - kMin + 1;

    DenselySampledSpectrum() = default;
    template <class F>
    static DenselySampledSpectrum from(F spectrum_of_nm) {
        DenselySampledSpectrum d;
        for (int i = 0; i < kCount; ++i) d.v_[i] = float(spectrum_of_nm(double(kMin + i)));
        return d;
    }

    // Linear interpolation between the two nearest nanometres.
    float operator()(float lambda) const {
        float t = lambda - float(kMin);
        if (!(t >= 0) || t > float(kCount - 1)) return 0;
        int i = int(t);
        if (i >= kCount - 1) return v_[kCount - 1];
        float f = t - float(i);
        return v_[i] + f * (v_[i + 1] - v_[i]);
    }
    SampledSpectrum sample(const SampledWavelengths& w) const {
        return {(*this)(w.lambda[0]), (*this)(w.lambda[1]), (*this)(w.lambda[2]), (*this)(w.lambda[3])};
    }
    void scale(float s) {
        for (float& x : v_) x *= s;
    }
    const std::array<float, kCount>& values() const { return v_; }

private:
    std::array<float, kCount> v_{};
};

} // namespace illum

// Participating media (Pharr, Jakob & Humphreys, PBR 4th ed., ch. 11): at each point an absorption and a
// scattering coefficient σ_a, σ_s [m^-1], a phase function and an emitted radiance Le (the source term
// σ_a Le), all at the path's wavelengths. A medium gives its majorant σ_maj ≥ σ_a + σ_s along a ray as
// piecewise-constant segments, against which the integrators' delta and ratio tracking sample
// (sample_majorant.h). Coordinates are world space; a medium keeps its own transform.
#pragma once

#include "illum/geometry/medium_interface.h"
#include "illum/geometry/ray.h"
#include "illum/medium/henyey_greenstein.h"
#include "illum/medium/majorant_grid.h"
#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

struct MediumProperties {
    SampledSpectrum sigma_a, sigma_s;
    HenyeyGreenstein phase;
    SampledSpectrum le; // emitted radiance; the source term is σ_a Le
};

class Medium {
public:
    virtual ~Medium() = default;
    virtual bool is_emissive() const = 0;
    // Whether σ_a, σ_s are the same everywhere and the majorant is σ_t itself (transmittance is then
    // exp(-σ_t d), which the integrators may evaluate instead of estimating it).
    virtual bool is_homogeneous() const { return false; }
    // The coefficients at world point p.
    virtual MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const = 0;
    // The majorant segments of `ray` (world space, unit direction) over t in [0, tmax).
    virtual MajorantIterator sample_ray(const Ray& ray, float tmax,
                                        const SampledWavelengths& lambda) const = 0;
    // A medium whose coefficients depend on where a path enters it (a textured subsurface material's): the
    // integrators evaluate it at the entry point and walk that instead (entry_medium.h).
    bool evaluated_at_entry() const { return evaluated_at_entry_; }
    // A medium so evaluated: the one it was evaluated from (else null).
    const Medium* entered_from() const { return entered_from_; }

protected:
    bool evaluated_at_entry_ = false;
    const Medium* entered_from_ = nullptr;
};

// A homogeneous medium's properties at a path's wavelengths, evaluated once for the path (they are the same
// everywhere, and the wavelengths do not change along a path).
class HomogeneousCache {
public:
    // Forget m's properties (an entry medium re-evaluated in place).
    void forget(const Medium* m) {
        if (medium_ == m) medium_ = nullptr;
    }
    const MediumProperties& get(const Medium& m, const SampledWavelengths& lambda) {
        if (&m != medium_) {
            props_ = m.sample_point(Point3f(), lambda);
            medium_ = &m;
        }
        return props_;
    }

private:
    const Medium* medium_ = nullptr;
    MediumProperties props_;
};

} // namespace illum

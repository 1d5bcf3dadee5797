// Media evaluated where a path enters them: a textured subsurface material's interior has the coefficients
// its textures give at the point where the path refracted into the shape, homogeneous for the whole walk
// inside (pbrt-v4's SubsurfaceMaterial::GetBSSRDF evaluates its textures once, at the BSSRDF's entry
// point; Cycles' random walk does the same). The integrators ask entered_medium() for the medium a ray
// leaving a surface travels in: it evaluates such a medium at the surface point into storage the path
// owns (no allocation), and keeps the path's evaluation when the ray was already inside it (a reflection
// off the inside of the boundary). Only a surface with a material can lead into such a medium (the
// subsurface material's shape), so rays crossing surfaces without material need not ask.
#pragma once

#include <new>

#include "illum/geometry/surface_hit.h"
#include "illum/medium/medium.h"

namespace illum {

// A medium's coefficients at one entry point, at the path's wavelengths (they do not change along a path):
// homogeneous, not emissive.
class EntryMedium final : public Medium {
public:
    EntryMedium() = default;
    // Its coefficients, evaluated from `from` (copies keep both, as vcm's stored light vertices need).
    void set(const Medium& from, SampledSpectrum sigma_a, SampledSpectrum sigma_s, HenyeyGreenstein phase) {
        entered_from_ = &from;
        props_.sigma_a = sigma_a;
        props_.sigma_s = sigma_s;
        props_.phase = phase;
    }
    bool is_emissive() const override { return false; }
    bool is_homogeneous() const override { return true; }
    MediumProperties sample_point(Point3f, const SampledWavelengths&) const override { return props_; }
    MajorantIterator sample_ray(const Ray&, float tmax, const SampledWavelengths&) const override {
        return MajorantIterator::single(0, tmax, props_.sigma_a + props_.sigma_s);
    }

private:
    MediumProperties props_;
};

// A medium evaluated at entry points.
class EntryEvaluatedMedium : public Medium {
public:
    EntryEvaluatedMedium() { evaluated_at_entry_ = true; }
    // Its coefficients at the entry point `at`, into *out.
    virtual void evaluate(const TextureEvalContext& at, const SampledWavelengths& lambda,
                          EntryMedium* out) const = 0;
};

// Per-path storage for N entry media, each made when first needed: a path that enters none initialises only
// the flags (kept before the storage, so that initialising the fields around it does not reach into it).
// EntryMedium owns nothing, so the objects are not destroyed.
template <int N>
class EntryMediumSlots {
public:
    EntryMediumSlots() = default;
    EntryMediumSlots(const EntryMediumSlots&) = delete;
    EntryMediumSlots& operator=(const EntryMediumSlots&) = delete;
    EntryMedium* get(int i) {
        if (!made_[i]) {
            ::new (static_cast<void*>(storage_[i])) EntryMedium();
            made_[i] = true;
        }
        return std::launder(reinterpret_cast<EntryMedium*>(storage_[i]));
    }

private:
    bool made_[N] = {};
    alignas(EntryMedium) unsigned char storage_[N][sizeof(EntryMedium)];
};

// The medium a ray that leaves `hit` travels in, given next = hit.medium_for(direction): next itself, unless
// it is evaluated at entry; then the medium of the ray that found the hit if that was evaluated from next
// (the path is inside already), else next evaluated at the hit into the storage `make_slot()` returns
// (asked only then, so a caller's storage is made, and a cache of its properties forgotten, only when it
// is filled).
template <class MakeSlot>
const Medium* entered_medium(const Medium* next, const SurfaceHit& hit, const SampledWavelengths& lambda,
                             MakeSlot&& make_slot) {
    if (!next || !next->evaluated_at_entry()) [[likely]]
        return next;
    if (hit.medium && hit.medium->entered_from() == next) return hit.medium;
    EntryMedium* slot = make_slot();
    static_cast<const EntryEvaluatedMedium*>(next)->evaluate(hit, lambda, slot);
    return slot;
}

} // namespace illum

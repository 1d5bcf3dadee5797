// Small helpers shared by the reflection models.
#pragma once

#include <string>

#include "illum/bsdf/bxdf.h"
#include "illum/util/error.h"

namespace illum {

// Mirror direction of w about the shading normal +z.
inline Vector3f reflect_z(Vector3f w) { return {-w.x, -w.y, w.z}; }

namespace bsdf_detail {
// Parameter validation for the model constructors (they throw illum::Error with a clear message).
[[noreturn]] inline void fail(const char* model, const std::string& what) {
    throw Error(std::string(model) + ": " + what);
}
inline bool in_range(float v, float lo, float hi) { return v >= lo && v <= hi; } // false for NaN
inline bool in_range(Color3 c, float lo, float hi) {
    return in_range(c.r, lo, hi) && in_range(c.g, lo, hi) && in_range(c.b, lo, hi);
}
inline std::string str(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}
inline std::string str(Color3 c) { return str(c.r) + "," + str(c.g) + "," + str(c.b); }
inline bool in_range(const SampledSpectrum& c, float lo, float hi) {
    for (int i = 0; i < kSpectrumSamples; ++i)
        if (!in_range(c[i], lo, hi)) return false;
    return true;
}
inline bool all_positive(const SampledSpectrum& c) {
    for (int i = 0; i < kSpectrumSamples; ++i)
        if (!(c[i] > 0)) return false;
    return true;
}
inline std::string str(const SampledSpectrum& c) {
    return str(c[0]) + "," + str(c[1]) + "," + str(c[2]) + "," + str(c[3]);
}
} // namespace bsdf_detail

// Throws illum::Error "model: what" unless ok. A macro so that the message (string concatenation) is built
// only on failure: materials construct models per hit, and that must not touch the heap.
#define ILLUM_REQUIRE(ok, model, what)                                                                       \
    do {                                                                                                     \
        if (!(ok)) ::illum::bsdf_detail::fail(model, what);                                                  \
    } while (0)

} // namespace illum

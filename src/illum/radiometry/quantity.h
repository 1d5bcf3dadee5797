// Radiometric quantities with their units in the type (DESIGN.md §3).
//
// A quantity carries integer exponents of watt, metre and steradian. Products and quotients add and
// subtract exponents; sums need equal units. So radiance [W m^-2 sr^-1] x solid angle [sr] is
// irradiance [W m^-2], a BRDF [sr^-1] x irradiance is radiance, and radiance + irradiance does not
// compile. A tag separates quantities that share units but not meaning: biradiance (intensity / r^2,
// before the cosine; McGuire's Graphics Codex) has the units of irradiance but is not one; a product
// drops the tag. Everything is a thin wrapper over SampledSpectrum (RGB or four wavelengths, by the path's
// mode) or float: zero cost at run time.
#pragma once

#include <cmath>
#include <type_traits>

#include "illum/radiometry/sampled_spectrum.h"

namespace illum {

struct NoTag {};
struct BiradianceTag {};
struct AreaPdfTag {};

// A scalar quantity (solid angle, area, a pdf) with units W^w m^m sr^s.
template <int W, int M, int S, class Tag = NoTag>
struct Scalar {
    float value = 0;
    constexpr Scalar() = default;
    constexpr explicit Scalar(float v) : value(v) {}
    constexpr Scalar operator+(Scalar o) const { return Scalar(value + o.value); }
    constexpr Scalar operator-(Scalar o) const { return Scalar(value - o.value); }
    constexpr Scalar operator*(float s) const { return Scalar(value * s); }
    constexpr Scalar operator/(float s) const { return Scalar(value / s); }
    Scalar& operator+=(Scalar o) { return *this = *this + o; }
    Scalar& operator*=(float s) { return *this = *this * s; }
    // Comparisons of the value (of one type only). Written out rather than a defaulted <=>: g++ 12 turns
    // `p > Scalar(0)` through std::partial_ordering into an extra unordered/equal test.
    constexpr bool operator==(Scalar o) const { return value == o.value; }
    constexpr bool operator!=(Scalar o) const { return value != o.value; }
    constexpr bool operator<(Scalar o) const { return value < o.value; }
    constexpr bool operator<=(Scalar o) const { return value <= o.value; }
    constexpr bool operator>(Scalar o) const { return value > o.value; }
    constexpr bool operator>=(Scalar o) const { return value >= o.value; }
    bool is_finite() const { return std::isfinite(value); }
};
// A dimensionless scalar is a plain float.
template <class Tag>
struct Scalar<0, 0, 0, Tag>;

template <int W, int M, int S, class Tag>
constexpr Scalar<W, M, S, Tag> operator*(float s, Scalar<W, M, S, Tag> q) {
    return q * s;
}

namespace detail {
template <int W, int M, int S>
struct ScalarOf {
    using type = Scalar<W, M, S>;
};
template <>
struct ScalarOf<0, 0, 0> {
    using type = float;
};
template <int W, int M, int S>
constexpr auto make_scalar(float v) {
    if constexpr (W == 0 && M == 0 && S == 0)
        return v;
    else
        return Scalar<W, M, S>(v);
}
} // namespace detail

// A plain number over a quantity has the inverse units: |cos θ| / p_ω is a solid angle [sr].
template <int W, int M, int S, class Tag>
constexpr auto operator/(float s, Scalar<W, M, S, Tag> q) {
    return detail::make_scalar<-W, -M, -S>(s / q.value);
}

template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator*(Scalar<W1, M1, S1, T1> a, Scalar<W2, M2, S2, T2> b) {
    return detail::make_scalar<W1 + W2, M1 + M2, S1 + S2>(a.value * b.value);
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator/(Scalar<W1, M1, S1, T1> a, Scalar<W2, M2, S2, T2> b) {
    return detail::make_scalar<W1 - W2, M1 - M2, S1 - S2>(a.value / b.value);
}

// A spectral quantity with units W^w m^m sr^s: its values at a path's wavelengths (or its RGB in RGB mode).
template <int W, int M, int S, class Tag = NoTag>
struct Quantity3 {
    SampledSpectrum s;
    constexpr Quantity3() = default;
    constexpr explicit Quantity3(SampledSpectrum v) : s(v) {}
    constexpr explicit Quantity3(float v) : s(v) {}
    // RGB mode's (r, g, b).
    constexpr Quantity3(float r, float g, float b) : s(Color3(r, g, b)) {}

    constexpr float operator[](int i) const { return s[i]; }
    constexpr Quantity3 operator+(Quantity3 o) const { return Quantity3(s + o.s); }
    constexpr Quantity3 operator-(Quantity3 o) const { return Quantity3(s - o.s); }
    constexpr Quantity3 operator*(float k) const { return Quantity3(s * k); }
    constexpr Quantity3 operator/(float k) const { return Quantity3(s / k); }
    // Scaling by a dimensionless reflectance or throughput keeps the units.
    constexpr Quantity3 operator*(SampledSpectrum c) const { return Quantity3(s * c); }
    Quantity3& operator+=(Quantity3 o) { return *this = *this + o; }
    Quantity3& operator*=(float k) { return *this = *this * k; }
    Quantity3& operator*=(SampledSpectrum c) { return *this = *this * c; }
    constexpr bool operator==(const Quantity3&) const = default;

    constexpr bool is_black() const { return s.is_black(); }
    constexpr float max_component() const { return s.max_component(); }
    // RGB mode: the colour in lanes 0-2 (a film value after its conversion to the output space).
    constexpr Color3 rgb() const { return s.rgb(); }
    bool is_finite() const { return s.is_finite(); }
    bool has_negative() const { return s.has_negative(); }
};

namespace detail {
template <int W, int M, int S>
constexpr auto make_quantity3(SampledSpectrum c) {
    if constexpr (W == 0 && M == 0 && S == 0)
        return c;
    else
        return Quantity3<W, M, S>(c);
}
} // namespace detail

template <int W, int M, int S, class T>
constexpr Quantity3<W, M, S, T> operator*(float s, Quantity3<W, M, S, T> q) {
    return q * s;
}
template <int W, int M, int S, class T>
constexpr Quantity3<W, M, S, T> operator*(SampledSpectrum c, Quantity3<W, M, S, T> q) {
    return q * c;
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator*(Quantity3<W1, M1, S1, T1> a, Quantity3<W2, M2, S2, T2> b) {
    return detail::make_quantity3<W1 + W2, M1 + M2, S1 + S2>(a.s * b.s);
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator/(Quantity3<W1, M1, S1, T1> a, Quantity3<W2, M2, S2, T2> b) {
    return detail::make_quantity3<W1 - W2, M1 - M2, S1 - S2>(a.s / b.s);
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator*(Quantity3<W1, M1, S1, T1> a, Scalar<W2, M2, S2, T2> b) {
    return detail::make_quantity3<W1 + W2, M1 + M2, S1 + S2>(a.s * b.value);
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator*(Scalar<W2, M2, S2, T2> b, Quantity3<W1, M1, S1, T1> a) {
    return a * b;
}
template <int W1, int M1, int S1, class T1, int W2, int M2, int S2, class T2>
constexpr auto operator/(Quantity3<W1, M1, S1, T1> a, Scalar<W2, M2, S2, T2> b) {
    return detail::make_quantity3<W1 - W2, M1 - M2, S1 - S2>(a.s / b.value);
}
// A dimensionless spectrum over a scalar quantity, e.g. a BSDF-weighted throughput divided by a pdf.
template <int W, int M, int S, class T>
constexpr auto operator/(SampledSpectrum a, Scalar<W, M, S, T> b) {
    return detail::make_quantity3<-W, -M, -S>(a / b.value);
}
template <int W, int M, int S, class T>
constexpr auto operator*(SampledSpectrum a, Scalar<W, M, S, T> b) {
    return detail::make_quantity3<W, M, S>(a * b.value);
}

// Scalars.
using SolidAngle = Scalar<0, 0, 1>;           // [sr]
using Area = Scalar<0, 2, 0>;                 // [m^2]
using SolidAnglePdf = Scalar<0, 0, -1>;       // probability per steradian [sr^-1]
using AreaPdf = Scalar<0, -2, 0, AreaPdfTag>; // probability per square metre [m^-2]
using AreaPerSolidAngle = Scalar<0, 2, -1>; // the Jacobian dA/dω of directions to surface points [m^2 sr^-1]
using Etendue = Scalar<0, 2, 1>;            // area x solid angle [m^2 sr]

// Spectral quantities.
using Power3 = Quantity3<1, 0, 0>;       // radiant flux [W]
using Intensity3 = Quantity3<1, 0, -1>;  // radiant intensity [W sr^-1]
using Irradiance3 = Quantity3<1, -2, 0>; // irradiance = radiosity = exitance [W m^-2]
using Radiosity3 = Irradiance3;
using Radiance3 = Quantity3<1, -2, -1>;                 // [W m^-2 sr^-1]
using Biradiance3 = Quantity3<1, -2, 0, BiradianceTag>; // intensity / r^2, before the cosine [W m^-2]
using Bsdf3 = Quantity3<0, 0, -1>;                      // BSDF value [sr^-1]

// Conversions the physics does, by name.

// A point source of intensity I at distance r delivers biradiance I / r^2.
constexpr Biradiance3 biradiance(Intensity3 i, float distance_squared) {
    return Biradiance3(i.s / distance_squared);
}
// Incident radiance over a pdf-sampled direction: the one-sample estimate of ∫ L dω, a biradiance that
// the reflection equation turns into radiance with f and the cosine.
constexpr Biradiance3 biradiance(Radiance3 l, SolidAnglePdf pdf) { return Biradiance3(l.s / pdf.value); }
// Radiance reflected by a BSDF from a biradiance arriving at angle θ: f · E_bi · cos θ.
constexpr Radiance3 reflected(Bsdf3 f, Biradiance3 e, float cos_theta) {
    return Radiance3(f.s * e.s * cos_theta);
}
// A collimated beam (a directional light) that delivers irradiance E_⊥ to a surface perpendicular to it
// has biradiance E_⊥: the cosine at the receiver is the reflection equation's, f · E_⊥ · cos θ.
constexpr Biradiance3 biradiance(Irradiance3 e_perpendicular) { return Biradiance3(e_perpendicular.s); }

// The Jacobian of the map from directions at a receiver to points on a surface at distance r whose
// normal makes the angle θ with the line of sight: dA = r^2 / |cos θ| dω (PBR 4th ed. §4.2.3).
constexpr AreaPerSolidAngle area_per_solid_angle(float distance_squared, float abs_cos) {
    return AreaPerSolidAngle(distance_squared / abs_cos);
}
// A pdf per unit area of a point at distance r seen at angle θ (cos of the angle between its normal and
// the line of sight) becomes a pdf per steradian: p_ω = p_A dA/dω = p_A r^2 / |cos θ| (PBR 4th ed.
// §6.1.4). Two forms of the same conversion, for their rounding: (p_A r^2) / |cos θ| here, and
// p_A (r^2 / |cos θ|) from the Jacobian above, which a sampler computes once for its sample.
constexpr SolidAnglePdf to_solid_angle(AreaPdf p, float distance_squared, float abs_cos) {
    return SolidAnglePdf(p.value * distance_squared / abs_cos);
}
constexpr SolidAnglePdf to_solid_angle(AreaPdf p, AreaPerSolidAngle jacobian) { return p * jacobian; }
// Irradiance on a surface from radiance over a solid angle at a cosine.
constexpr Irradiance3 irradiance(Radiance3 l, SolidAngle w, float cos_theta) {
    return Irradiance3(l.s * w.value * cos_theta);
}
// The exitance of a Lambertian emitter of radiance L: M = π L; its power over an area A: Φ = π A L.
constexpr Irradiance3 lambertian_exitance(Radiance3 l) { return Irradiance3(l.s * 3.14159265358979323846f); }

// Estimators.

// The throughput weight of a direction ω_i sampled with solid-angle density p: f(ω_o, ω_i) |cos θ_i| / p
// (dimensionless: [sr^-1] [sr^-1]^-1), the factor that one bounce adds to a path's throughput in the
// Monte Carlo estimate of the rendering equation (PBR 4th ed. §13.1). Evaluated as
// f · (|cos θ_i| / p).
constexpr SampledSpectrum throughput_weight(Bsdf3 f, float abs_cos, SolidAnglePdf pdf) {
    return f * (abs_cos / pdf);
}

// The power heuristic with β = 2 (Veach 1997, §9.2.4): w_a = p_a^2 / (p_a^2 + p_b^2), for one sample
// from each of two strategies. The weights only sum to one when both densities are over the same measure
// (both per steradian, say), so both arguments have one type: mixing an area pdf with a solid-angle pdf,
// or a pdf with a plain number, does not compile. An infinite p_a (a delta) takes the whole weight.
template <int W, int M, int S, class Tag>
inline float power_heuristic(Scalar<W, M, S, Tag> pdf_a, Scalar<W, M, S, Tag> pdf_b) {
    float a = pdf_a.value * pdf_a.value, b = pdf_b.value * pdf_b.value;
    if (std::isinf(a)) return 1;
    return a + b > 0 ? a / (a + b) : 0.0f;
}

} // namespace illum

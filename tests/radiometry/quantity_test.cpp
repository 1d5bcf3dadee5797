// The unit system compiles only physically meaningful operations (DESIGN.md §3).
#include "illum/radiometry/quantity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <concepts>
#include <type_traits>

namespace illum {
namespace {

template <class A, class B>
concept Addable = requires(A a, B b) {
    a + b;
};
template <class A, class B>
concept Multipliable = requires(A a, B b) {
    a* b;
};
template <class A, class B>
using Product = decltype(std::declval<A>() * std::declval<B>());
template <class A, class B>
using Quotient = decltype(std::declval<A>() / std::declval<B>());

// Sums need equal units.
static_assert(Addable<Radiance3, Radiance3>);
static_assert(!Addable<Radiance3, Irradiance3>);
static_assert(!Addable<Irradiance3, Biradiance3>); // same units, different meaning
static_assert(!Addable<Power3, Intensity3>);
static_assert(!Addable<Radiance3, SampledSpectrum>);
static_assert(!Addable<SolidAnglePdf, AreaPdf>);

// Products and quotients carry units.
static_assert(std::is_same_v<Product<Radiance3, SolidAngle>, Irradiance3>);
static_assert(std::is_same_v<Product<Bsdf3, Irradiance3>, Radiance3>);
static_assert(std::is_same_v<Product<Bsdf3, Biradiance3>, Radiance3>);
static_assert(std::is_same_v<Product<Irradiance3, Area>, Power3>);
static_assert(std::is_same_v<Product<Intensity3, SolidAngle>, Power3>);
static_assert(std::is_same_v<Quotient<Radiance3, SolidAnglePdf>, Irradiance3>);
static_assert(std::is_same_v<Quotient<Bsdf3, SolidAnglePdf>, SampledSpectrum>); // f / pdf is a weight
static_assert(std::is_same_v<Quotient<Radiance3, Radiance3>, SampledSpectrum>);
static_assert(std::is_same_v<Product<SolidAnglePdf, SolidAngle>, float>);
// Scaling by a dimensionless reflectance keeps the units.
static_assert(std::is_same_v<Product<Radiance3, SampledSpectrum>, Radiance3>);
static_assert(std::is_same_v<Product<SampledSpectrum, Power3>, Power3>);
static_assert(std::is_same_v<Product<Radiance3, float>, Radiance3>);
// There is no implicit conversion between quantities, or from SampledSpectrum.
static_assert(!std::is_convertible_v<Radiance3, Irradiance3>);
static_assert(!std::is_convertible_v<SampledSpectrum, Radiance3>);
static_assert(!std::is_convertible_v<Radiance3, SampledSpectrum>);
static_assert(!std::is_convertible_v<float, SolidAnglePdf>);

// Multiple importance sampling weighs densities over one measure: the power heuristic takes two pdfs of the
// same type, so an area pdf against a solid-angle pdf, or a pdf against a plain number, does not compile.
template <class A, class B>
concept PowerHeuristicOf = requires(A a, B b) {
    { power_heuristic(a, b) } -> std::same_as<float>;
};
static_assert(PowerHeuristicOf<SolidAnglePdf, SolidAnglePdf>);
static_assert(PowerHeuristicOf<AreaPdf, AreaPdf>);
static_assert(!PowerHeuristicOf<SolidAnglePdf, AreaPdf>);
static_assert(!PowerHeuristicOf<AreaPdf, SolidAnglePdf>);
static_assert(!PowerHeuristicOf<SolidAnglePdf, float>);
static_assert(!PowerHeuristicOf<float, float>);
// Densities compare only within one measure.
template <class A, class B>
concept Comparable = requires(A a, B b) {
    { a < b } -> std::same_as<bool>;
};
static_assert(Comparable<SolidAnglePdf, SolidAnglePdf>);
static_assert(!Comparable<SolidAnglePdf, AreaPdf>);
static_assert(!Comparable<SolidAnglePdf, float>);
// A light-selection probability (a plain number) times a density keeps the density's measure.
static_assert(std::is_same_v<Product<float, SolidAnglePdf>, SolidAnglePdf>);
static_assert(std::is_same_v<Product<float, AreaPdf>, AreaPdf>);

// Area to solid angle: p_A dA/dω is per steradian; an area pdf is not a solid-angle one without it.
static_assert(std::is_same_v<Product<AreaPdf, AreaPerSolidAngle>, SolidAnglePdf>);
static_assert(std::is_same_v<decltype(to_solid_angle(AreaPdf(1), 1.0f, 1.0f)), SolidAnglePdf>);
static_assert(!std::is_convertible_v<AreaPdf, SolidAnglePdf>);
static_assert(!std::is_assignable_v<SolidAnglePdf&, AreaPdf>);
static_assert(!Addable<AreaPdf, Area>);

// The throughput is dimensionless: a BSDF value [sr^-1] times |cos θ| over a solid-angle pdf [sr^-1].
static_assert(
    std::is_same_v<decltype(throughput_weight(Bsdf3(1.0f), 1.0f, SolidAnglePdf(1))), SampledSpectrum>);
static_assert(std::is_same_v<Product<Bsdf3, Quotient<float, SolidAnglePdf>>, SampledSpectrum>);
static_assert(std::is_same_v<Quotient<float, SolidAnglePdf>, SolidAngle>);
// An area pdf in the throughput leaves units behind (m^2 sr^-1): not a weight a SampledSpectrum can take.
static_assert(!std::is_same_v<Quotient<Bsdf3, AreaPdf>, SampledSpectrum>);
static_assert(!std::is_assignable_v<SampledSpectrum&, Quotient<Bsdf3, AreaPdf>>);
// A pdf is not a throughput: adding one to a throughput, or scaling a throughput into a pdf, fails.
static_assert(!Addable<SampledSpectrum, SolidAnglePdf>);
static_assert(!Addable<SolidAnglePdf, SampledSpectrum>);
static_assert(!Addable<SampledSpectrum, AreaPdf>);
static_assert(!Addable<float, SolidAnglePdf>);
static_assert(!std::is_assignable_v<SampledSpectrum&, SolidAnglePdf>);
// What an estimate adds up is radiance: not irradiance, biradiance, a throughput or a pdf.
static_assert(!Addable<Radiance3, Biradiance3>);
static_assert(!Addable<Radiance3, SolidAnglePdf>);
static_assert(!std::is_assignable_v<Radiance3&, Irradiance3>);
static_assert(std::is_same_v<Product<Radiance3, SampledSpectrum>, Radiance3>); // L β
static_assert(std::is_same_v<decltype(reflected(Bsdf3(), Biradiance3(), 1.0f)), Radiance3>);
static_assert(std::is_same_v<Product<Intensity3, SolidAngle>, Power3>); // Φ = 4π I
static_assert(std::is_same_v<Product<Irradiance3, Area>, Power3>);      // Φ = M A
static_assert(std::is_same_v<Product<Radiance3, Etendue>, Power3>);     // Φ = L G

// Zero cost: the wrappers are the size of what they wrap.
static_assert(sizeof(Radiance3) == sizeof(SampledSpectrum));
static_assert(sizeof(SolidAnglePdf) == sizeof(float));
static_assert(std::is_trivially_copyable_v<Radiance3>);

TEST(Quantity, NamedConversionsDoThePhysics) {
    // A point source of 8 W/sr at 2 m delivers 2 W/m^2 of biradiance.
    Biradiance3 e = biradiance(Intensity3(8.0f), 4.0f);
    EXPECT_FLOAT_EQ(e[0], 2.0f);
    // A white Lambertian BRDF (1/π) under that biradiance at normal incidence reflects 2/π W m^-2 sr^-1.
    Radiance3 l = reflected(Bsdf3(0.31830988618379067154f), e, 1.0f);
    EXPECT_FLOAT_EQ(l[1], 2.0f / 3.14159265f);
    // Area pdf to solid-angle pdf: p_A r^2 / cos.
    EXPECT_FLOAT_EQ(to_solid_angle(AreaPdf(0.5f), 4.0f, 0.5f).value, 4.0f);
    // Radiance over a solid angle at a cosine is irradiance.
    EXPECT_FLOAT_EQ(irradiance(Radiance3(2.0f), SolidAngle(0.5f), 0.5f)[2], 0.5f);
    EXPECT_FLOAT_EQ(lambertian_exitance(Radiance3(1.0f))[0], 3.14159265f);
    // The Jacobian form gives the same conversion: 0.5 m^-2 x (4 / 0.5) m^2 sr^-1 = 4 sr^-1.
    EXPECT_FLOAT_EQ(to_solid_angle(AreaPdf(0.5f), area_per_solid_angle(4.0f, 0.5f)).value, 4.0f);
    // A white Lambertian BRDF sampled by the cosine: f |cos| / p = (1/π) cos / (cos/π) = 1.
    EXPECT_FLOAT_EQ(
        throughput_weight(Bsdf3(0.31830988618379067154f), 0.5f, SolidAnglePdf(0.5f / 3.14159265f))[0], 1.0f);
}

TEST(Quantity, PowerHeuristicWeighsSameMeasureDensities) {
    // w_a = p_a^2 / (p_a^2 + p_b^2); the two weights sum to one.
    SolidAnglePdf a(3), b(1);
    EXPECT_FLOAT_EQ(power_heuristic(a, b), 0.9f);
    EXPECT_FLOAT_EQ(power_heuristic(a, b) + power_heuristic(b, a), 1.0f);
    EXPECT_EQ(power_heuristic(SolidAnglePdf(0), SolidAnglePdf(0)), 0.0f);
    EXPECT_EQ(power_heuristic(SolidAnglePdf(INFINITY), SolidAnglePdf(1)), 1.0f);
}

} // namespace
} // namespace illum

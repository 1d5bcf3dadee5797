// The unit system compiles only physically meaningful operations (DESIGN.md §3).
#include "illum/radiometry/quantity.h"

#include <gtest/gtest.h>

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
static_assert(!Addable<Radiance3, Color3>);
static_assert(!Addable<SolidAnglePdf, AreaPdf>);

// Products and quotients carry units.
static_assert(std::is_same_v<Product<Radiance3, SolidAngle>, Irradiance3>);
static_assert(std::is_same_v<Product<Bsdf3, Irradiance3>, Radiance3>);
static_assert(std::is_same_v<Product<Bsdf3, Biradiance3>, Radiance3>);
static_assert(std::is_same_v<Product<Irradiance3, Area>, Power3>);
static_assert(std::is_same_v<Product<Intensity3, SolidAngle>, Power3>);
static_assert(std::is_same_v<Quotient<Radiance3, SolidAnglePdf>, Irradiance3>);
static_assert(std::is_same_v<Quotient<Bsdf3, SolidAnglePdf>, Color3>); // f / pdf is a weight
static_assert(std::is_same_v<Quotient<Radiance3, Radiance3>, Color3>);
static_assert(std::is_same_v<Product<SolidAnglePdf, SolidAngle>, float>);
// Scaling by a dimensionless reflectance keeps the units.
static_assert(std::is_same_v<Product<Radiance3, Color3>, Radiance3>);
static_assert(std::is_same_v<Product<Color3, Power3>, Power3>);
static_assert(std::is_same_v<Product<Radiance3, float>, Radiance3>);
// There is no implicit conversion between quantities, or from Color3.
static_assert(!std::is_convertible_v<Radiance3, Irradiance3>);
static_assert(!std::is_convertible_v<Color3, Radiance3>);
static_assert(!std::is_convertible_v<Radiance3, Color3>);
static_assert(!std::is_convertible_v<float, SolidAnglePdf>);

// Zero cost: the wrappers are the size of what they wrap.
static_assert(sizeof(Radiance3) == sizeof(Color3));
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
}

} // namespace
} // namespace illum

// The derivatives of (s, t) that the mappings give for a footprint (TextureMapping2D::map_footprint)
// against central differences of map() along ∂p/∂x and ∂p/∂y.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/texture/mapping.h"

namespace illum {
namespace {

TextureEvalContext footprint(Point3f p, Vector3f dpdx, Vector3f dpdy) {
    TextureEvalContext c;
    c.p = p;
    c.dpdx = dpdx;
    c.dpdy = dpdy;
    return c;
}

void expect_matches_differences(const TextureMapping2D& m, Point3f p, Vector3f dx, Vector3f dy) {
    TexCoord2D c = m.map_footprint(footprint(p, dx, dy));
    // ∂s/∂x ≈ (s(p + h dx) - s(p - h dx)) / 2h.
    const float h = 1e-2f;
    auto diff = [&](Vector3f d) {
        TextureEvalContext a = footprint(p + d * h, {}, {}), b = footprint(p - d * h, {}, {});
        Point2f sa = m.map(a), sb = m.map(b);
        return Vector2f((sa.x - sb.x) / (2 * h), (sa.y - sb.y) / (2 * h));
    };
    Vector2f fx = diff(dx), fy = diff(dy);
    float scale = std::max({std::abs(fx.x), std::abs(fx.y), std::abs(fy.x), std::abs(fy.y)});
    float tol = 1e-3f * scale + 1e-5f;
    EXPECT_NEAR(c.dsdx, fx.x, tol);
    EXPECT_NEAR(c.dtdx, fx.y, tol);
    EXPECT_NEAR(c.dsdy, fy.x, tol);
    EXPECT_NEAR(c.dtdy, fy.y, tol);
}

const Transform kTextureFromWorld =
    Transform::rotate(30, Vector3f(1, 2, 0.5f)) * Transform::translate(Vector3f(0.3f, -0.2f, 0.1f));

TEST(MappingFootprint, Spherical) {
    auto m = TextureMapping2D::spherical(kTextureFromWorld);
    expect_matches_differences(m, {0.4f, 0.7f, -0.5f}, {0.3f, -0.1f, 0.2f}, {-0.05f, 0.2f, 0.4f});
    expect_matches_differences(m, {-1.2f, 0.1f, 0.9f}, {0.1f, 0.5f, 0}, {0, -0.2f, 0.3f});
}

TEST(MappingFootprint, Cylindrical) {
    auto m = TextureMapping2D::cylindrical(kTextureFromWorld);
    expect_matches_differences(m, {0.4f, 0.7f, -0.5f}, {0.3f, -0.1f, 0.2f}, {-0.05f, 0.2f, 0.4f});
}

TEST(MappingFootprint, Planar) {
    auto m = TextureMapping2D::planar(kTextureFromWorld, {1, 0.5f, 0}, {0, 0.25f, 2}, 0.1f, 0.2f);
    expect_matches_differences(m, {0.4f, 0.7f, -0.5f}, {0.3f, -0.1f, 0.2f}, {-0.05f, 0.2f, 0.4f});
}

TEST(MappingFootprint, UVScalesTheUvDerivatives) {
    auto m = TextureMapping2D::uv(2, 3, 0.5f, -1);
    TextureEvalContext c;
    c.dudx = 0.1f, c.dudy = 0.2f, c.dvdx = -0.3f, c.dvdy = 0.4f;
    TexCoord2D t = m.map_footprint(c);
    EXPECT_FLOAT_EQ(t.dsdx, 0.2f);
    EXPECT_FLOAT_EQ(t.dsdy, 0.4f);
    EXPECT_FLOAT_EQ(t.dtdx, -0.9f);
    EXPECT_FLOAT_EQ(t.dtdy, 1.2f);
}

} // namespace
} // namespace illum

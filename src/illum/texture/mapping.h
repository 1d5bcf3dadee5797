// pbrt-v4's texture mappings (PBR 4th ed. §10.2): where a texture looks itself up at a surface point.
// 2D mappings give (s, t): "uv" from the surface's (u, v) scaled and offset; "spherical", "cylindrical" and
// "planar" from the point in the texture's own space (the inverse of the CTM at its Texture directive). The
// 3D mapping of solid textures is that point itself. map_footprint also gives the derivatives of (s, t) in
// x and y from the context's footprint (pbrt-v4's TexCoord2D): the uv mapping scales ∂u/∂x...; the others
// take ∂p/∂x, ∂p/∂y to the texture's space and dot them with ∂s/∂p, ∂t/∂p:
//   spherical: ∂s/∂p = ∂θ/∂p / π = (xz/ρ, yz/ρ, -ρ) / (π r²), ∂t/∂p = ∂φ/∂p / 2π = (-y, x, 0) / (2π ρ²)
//     (r = |p|, ρ = sqrt(x² + y²)); pbrt-v4 (5f7a606) pairs ∂φ/∂p with s and ∂θ/∂p with t, the reverse of
//     its own (s, t) = (θ/π, φ/2π); illum pairs each with its own coordinate;
//   cylindrical: ∂s/∂p = (-y, x, 0) / (2π ρ²), ∂t/∂p = (0, 0, 1); planar: ∂s/∂p = vs, ∂t/∂p = vt.
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/math/transform.h"
#include "illum/texture/texture.h"

namespace illum {

// (s, t) and their derivatives in raster x and y.
struct TexCoord2D {
    Point2f st;
    float dsdx = 0, dsdy = 0, dtdx = 0, dtdy = 0;
};

class TextureMapping2D {
public:
    enum class Kind { UV, Spherical, Cylindrical, Planar };

    // (s, t) = (su u + du, sv v + dv).
    static TextureMapping2D uv(float su, float sv, float du, float dv) {
        TextureMapping2D m;
        m.su_ = su, m.sv_ = sv, m.du_ = du, m.dv_ = dv;
        return m;
    }
    // For the point p' = texture_from_world(p): spherical (s, t) = (θ/π, φ/2π) of the direction to p' (θ from
    // +z, φ = atan2(y, x) in [0, 2π)); cylindrical (s, t) = ((π + atan2(y, x))/2π, z); planar
    // (s, t) = (du + p'·vs, dv + p'·vt).
    static TextureMapping2D spherical(const Transform& texture_from_world) {
        return TextureMapping2D(Kind::Spherical, texture_from_world);
    }
    static TextureMapping2D cylindrical(const Transform& texture_from_world) {
        return TextureMapping2D(Kind::Cylindrical, texture_from_world);
    }
    static TextureMapping2D planar(const Transform& texture_from_world, Vector3f vs, Vector3f vt, float du,
                                   float dv) {
        TextureMapping2D m(Kind::Planar, texture_from_world);
        m.vs_ = vs, m.vt_ = vt, m.du_ = du, m.dv_ = dv;
        return m;
    }

    Kind kind() const { return kind_; }

    Point2f map(const TextureEvalContext& hit) const {
        if (kind_ == Kind::UV) return {su_ * hit.uv.x + du_, sv_ * hit.uv.y + dv_};
        Point3f p = texture_from_world_(hit.p);
        Vector3f v(p.x, p.y, p.z);
        switch (kind_) {
        case Kind::Spherical: {
            float len = length(v);
            if (!(len > 0)) return {0, 0};
            v = v / len;
            float theta = std::acos(std::clamp(v.z, -1.0f, 1.0f));
            float phi = std::atan2(v.y, v.x);
            if (phi < 0) phi += 2 * kPi;
            return {theta / kPi, phi / (2 * kPi)};
        }
        case Kind::Cylindrical:
            return {(kPi + std::atan2(p.y, p.x)) / (2 * kPi), p.z};
        case Kind::Planar:
            return {du_ + dot(v, vs_), dv_ + dot(v, vt_)};
        case Kind::UV:
            break;
        }
        return {0, 0};
    }

    TexCoord2D map_footprint(const TextureEvalContext& hit) const {
        TexCoord2D c;
        c.st = map(hit);
        if (kind_ == Kind::UV) {
            c.dsdx = su_ * hit.dudx, c.dsdy = su_ * hit.dudy;
            c.dtdx = sv_ * hit.dvdx, c.dtdy = sv_ * hit.dvdy;
            return c;
        }
        Point3f p = texture_from_world_(hit.p);
        Vector3f dsdp, dtdp;
        float rho2 = p.x * p.x + p.y * p.y;
        switch (kind_) {
        case Kind::Spherical: {
            float r2 = rho2 + p.z * p.z, rho = std::sqrt(rho2);
            if (!(rho > 0)) return c; // on the axis: φ is undefined
            dsdp = Vector3f(p.x * p.z / rho, p.y * p.z / rho, -rho) / (kPi * r2);
            dtdp = Vector3f(-p.y, p.x, 0) / (2 * kPi * rho2);
            break;
        }
        case Kind::Cylindrical:
            if (!(rho2 > 0)) return c;
            dsdp = Vector3f(-p.y, p.x, 0) / (2 * kPi * rho2);
            dtdp = Vector3f(0, 0, 1);
            break;
        case Kind::Planar:
            dsdp = vs_, dtdp = vt_;
            break;
        case Kind::UV:
            break;
        }
        Vector3f dpdx = texture_from_world_(hit.dpdx), dpdy = texture_from_world_(hit.dpdy);
        c.dsdx = dot(dsdp, dpdx), c.dsdy = dot(dsdp, dpdy);
        c.dtdx = dot(dtdp, dpdx), c.dtdy = dot(dtdp, dpdy);
        return c;
    }

private:
    TextureMapping2D() = default;
    TextureMapping2D(Kind k, const Transform& t) : kind_(k), texture_from_world_(t) {}

    Kind kind_ = Kind::UV;
    float su_ = 1, sv_ = 1, du_ = 0, dv_ = 0;
    Vector3f vs_{1, 0, 0}, vt_{0, 1, 0};
    Transform texture_from_world_;
};

// The 3D mapping of solid textures: the point in the texture's space.
class TextureMapping3D {
public:
    explicit TextureMapping3D(const Transform& texture_from_world)
        : texture_from_world_(texture_from_world) {}
    Point3f map(const TextureEvalContext& hit) const { return texture_from_world_(hit.p); }
    // ∂p/∂x and ∂p/∂y in the texture's space.
    Vector3f dpdx(const TextureEvalContext& hit) const { return texture_from_world_(hit.dpdx); }
    Vector3f dpdy(const TextureEvalContext& hit) const { return texture_from_world_(hit.dpdy); }

private:
    Transform texture_from_world_;
};

} // namespace illum

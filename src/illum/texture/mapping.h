// pbrt-v4's texture mappings (PBR 4th ed. §10.2): where a texture looks itself up at a surface point.
// 2D mappings give (s, t): "uv" from the surface's (u, v) scaled and offset; "spherical", "cylindrical" and
// "planar" from the point in the texture's own space (the inverse of the CTM at its Texture directive). The
// 3D mapping of solid textures is that point itself. Ray differentials are not carried, so the (s, t) come
// without their derivatives (textures are point-sampled).
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/math/transform.h"
#include "illum/texture/texture.h"

namespace illum {

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
    explicit TextureMapping3D(const Transform& texture_from_world) : texture_from_world_(texture_from_world) {}
    Point3f map(const TextureEvalContext& hit) const { return texture_from_world_(hit.p); }

private:
    Transform texture_from_world_;
};

} // namespace illum

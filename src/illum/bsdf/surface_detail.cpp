#include "illum/bsdf/surface_detail.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/math/frame.h"

namespace illum {

SurfaceDetail::SurfaceDetail(const FloatTexture* displacement, std::shared_ptr<const Image> normal_map)
    : displacement_(displacement), normal_map_image_(std::move(normal_map)) {
    if (normal_map_image_)
        normal_map_ = std::make_unique<ImageTextureData>(normal_map_image_, WrapMode::Repeat, 1.0f, false);
}

void SurfaceDetail::normal_map_tangents(const SurfaceHit& hit, Vector3f* dpdu, Vector3f* dpdv) const {
    // ImageTextureData looks up (s, 1 - t): pbrt-v4's (u, 1 - v) for normal maps.
    Color3 c = normal_map_->lookup(hit.uv);
    Vector3f nt = normalize(Vector3f(2 * c.r - 1, 2 * c.g - 1, 2 * c.b - 1));
    // The tangent frame: x along ∂p/∂u, z the shading normal, y = z × x.
    Vector3f x = normalize(hit.dpdu), z(hit.ns);
    Vector3f ns = x * nt.x + cross(z, x) * nt.y + z * nt.z;
    float ulen = length(hit.dpdu), vlen = length(hit.dpdv);
    // ∂p/∂u: its component orthogonal to the new normal, at its old length; ∂p/∂v completes the frame.
    Vector3f u = hit.dpdu - ns * dot(hit.dpdu, ns);
    *dpdu = normalize(u) * ulen;
    *dpdv = normalize(cross(ns, *dpdu)) * vlen;
}

void SurfaceDetail::bump_tangents(const SurfaceHit& hit, Vector3f* dpdu, Vector3f* dpdv) const {
    // pbrt-v4's BumpMap: steps of half the footprint's extent in u and in v, .0005 where it is zero.
    float du = .5f * (std::abs(hit.dudx) + std::abs(hit.dudy));
    float dv = .5f * (std::abs(hit.dvdx) + std::abs(hit.dvdy));
    if (du == 0) du = kBumpDelta;
    if (dv == 0) dv = kBumpDelta;
    TextureEvalContext shifted = hit;
    shifted.p = hit.p + hit.dpdu * du;
    shifted.uv = {hit.uv.x + du, hit.uv.y};
    float d_u = displacement_->evaluate(shifted);
    shifted.p = hit.p + hit.dpdv * dv;
    shifted.uv = {hit.uv.x, hit.uv.y + dv};
    float d_v = displacement_->evaluate(shifted);
    float d = displacement_->evaluate(hit);
    Vector3f n(hit.ns);
    *dpdu = hit.dpdu + n * ((d_u - d) / du) + Vector3f(hit.dndu) * d;
    *dpdv = hit.dpdv + n * ((d_v - d) / dv) + Vector3f(hit.dndv) * d;
}

void SurfaceDetail::apply(SurfaceHit& hit) const {
    hit.complete_shading_partials();
    Vector3f dpdu, dpdv;
    if (normal_map_)
        normal_map_tangents(hit, &dpdu, &dpdv);
    else
        bump_tangents(hit, &dpdu, &dpdv);
    Vector3f c = cross(dpdu, dpdv);
    float len2 = length_squared(c);
    if (!(len2 > 0) || !std::isfinite(len2) || !is_finite(dpdu) || !is_finite(dpdv)) [[unlikely]]
        return;
    // pbrt-v4's SetShadingGeometry with the geometric normal authoritative: the new normal turned to its
    // side; tangents of extreme length scaled down together (only their directions and ratio matter).
    hit.ns = face_forward(Normal3f(c / std::sqrt(len2)), Vector3f(hit.n));
    while (length_squared(dpdu) > 1e16f || length_squared(dpdv) > 1e16f) {
        dpdu = dpdu / 1e8f;
        dpdv = dpdv / 1e8f;
    }
    hit.dpdu = dpdu;
    hit.dpdv = dpdv;
}

std::unique_ptr<const SurfaceDetail> read_surface_detail(const EntityDesc& m, TextureParams& textures) {
    const FloatTexture* displacement = textures.scalar(m.params, "displacement", std::nullopt);
    std::shared_ptr<const Image> normal_map;
    if (const Param* p = m.params.find("normalmap")) {
        std::string path = m.params.get_string("normalmap", ""); // throws at p for a wrong type
        if (!path.empty()) {
            normal_map = read_encoded_image(path, "linear", 1, p->loc, textures);
            if (normal_map && normal_map->empty()) throw Error(p->loc, "the normal map image is empty");
        }
    }
    if (!displacement && !normal_map) return nullptr;
    return std::make_unique<const SurfaceDetail>(displacement, std::move(normal_map));
}

} // namespace illum

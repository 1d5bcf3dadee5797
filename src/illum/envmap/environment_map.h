// An environment map: an image of radiance over the sphere of directions in one of the layouts of
// layout.h, with bilinear lookup by direction and the exact solid angle of each texel.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "illum/envmap/layout.h"
#include "illum/image/image.h"

namespace illum {

class EnvironmentMap {
public:
    EnvironmentMap() = default;
    // Throws illum::Error when the image's aspect ratio does not fit the layout. Non-finite and negative
    // texels are set to 0 (an environment emits no negative radiance); non_finite_count() says how many.
    EnvironmentMap(Image image, EnvLayout layout, const std::string& what = "environment map");

    // Reads an HDR image (.exr, .pfm, .hdr; an 8-bit .png/.jpg is refused: it holds no radiance). With
    // no layout given, it follows the aspect ratio: 2:1 latlong, 1:1 octahedral, 6:1 cubemap.
    static EnvironmentMap load(const std::string& path, std::optional<EnvLayout> layout = std::nullopt);
    // The layout an image of this size defaults to; throws illum::Error naming `what` if none fits.
    static EnvLayout default_layout(int width, int height, const std::string& what);

    EnvLayout layout() const { return layout_; }
    const Image& image() const { return image_; }
    int width() const { return image_.width(); }
    int height() const { return image_.height(); }
    std::size_t non_finite_count() const { return sanitized_; }

    // Radiance towards direction d (unit, map frame), bilinear between texel centres with the layout's
    // wrapping (latlong wraps in φ, octahedral folds over its edges, the others clamp).
    Color3 lookup(Vector3f d) const;
    // Bilinear lookup at image coordinates uv in [0, 1]².
    Color3 lookup_uv(Point2f uv) const;
    // The texel's value (no filtering).
    const Color3& texel(int x, int y) const { return image_(x, y); }

    // Direction through the centre of texel (x, y); nullopt outside the layout's domain.
    std::optional<Vector3f> texel_direction(int x, int y) const;
    // Solid angle of texel (x, y): exact for latlong (Δφ (cos θ0 - cos θ1)) and octahedral (4π / N²),
    // integrated over 4x4 sub-texels for the others (the probe disks' rims, the cube's faces).
    float texel_solid_angle(int x, int y) const;
    // Per-texel solid angles, row by row (computed once, on first use; not thread-safe before that).
    const std::vector<float>& solid_angles() const;

    // ∫ L dω / 4π per channel: the mean radiance over the sphere.
    Color3 mean_radiance() const;

private:
    Color3 fetch(int x, int y) const; // with the layout's wrapping

    Image image_;
    EnvLayout layout_ = EnvLayout::LatLong;
    std::size_t sanitized_ = 0;
    mutable std::vector<float> solid_angles_;
};

} // namespace illum

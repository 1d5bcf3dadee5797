#include "illum/envmap/environment_map.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "illum/image/image_io.h"
#include "illum/util/error.h"

namespace illum {

EnvironmentMap::EnvironmentMap(Image image, EnvLayout layout, const std::string& what)
    : image_(std::move(image)), layout_(layout) {
    check_env_layout_size(layout, image_.width(), image_.height(), what);
    Color3* p = image_.data();
    for (std::size_t i = 0; i < image_.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) {
            float v = p[i][c];
            if (!std::isfinite(v) || v < 0) {
                if (!std::isfinite(v)) ++sanitized_;
                p[i][c] = 0;
            }
        }
    }
}

EnvLayout EnvironmentMap::default_layout(int width, int height, const std::string& what) {
    if (height > 0 && width == 2 * height) return EnvLayout::LatLong;
    if (height > 0 && width == height) return EnvLayout::Octahedral;
    if (height > 0 && width == 6 * height) return EnvLayout::Cubemap;
    throw Error(fmt::format("{}: an environment map must be 2:1 (latlong), 1:1 (octahedral, mirror ball or "
                            "angular map) or 6:1 (cubemap strip), not {}x{}",
                            what, width, height));
}

EnvironmentMap EnvironmentMap::load(const std::string& path, std::optional<EnvLayout> layout) {
    std::string ext = image_extension(path);
    if (ext != ".exr" && ext != ".pfm" && ext != ".hdr")
        throw Error(
            fmt::format("\"{}\": an environment map must be a high-dynamic-range image (.exr, .pfm or "
                        ".hdr), not \"{}\"",
                        path, ext));
    Image img = read_image(path);
    std::string what = fmt::format("\"{}\"", path);
    EnvLayout l = layout ? *layout : default_layout(img.width(), img.height(), what);
    return EnvironmentMap(std::move(img), l, what);
}

Color3 EnvironmentMap::fetch(int x, int y) const {
    int w = image_.width(), h = image_.height();
    switch (layout_) {
    case EnvLayout::LatLong:
        // Across a pole: the texel on the other side of it (φ + π).
        if (y < 0) {
            y = -y - 1;
            x += w / 2;
        } else if (y >= h) {
            y = 2 * h - y - 1;
            x += w / 2;
        }
        x = ((x % w) + w) % w;
        y = std::clamp(y, 0, h - 1);
        break;
    case EnvLayout::Octahedral:
        // The equal-area octahedral square folds over each edge onto itself mirrored (pbrt-v4's
        // OctahedralSphere wrap): leaving through the left edge at row y enters at row h-1-y.
        if (x < 0) {
            x = -x - 1;
            y = h - 1 - y;
        } else if (x >= w) {
            x = 2 * w - 1 - x;
            y = h - 1 - y;
        }
        if (y < 0) {
            y = -y - 1;
            x = w - 1 - x;
        } else if (y >= h) {
            y = 2 * h - 1 - y;
            x = w - 1 - x;
        }
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        break;
    default:
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        break;
    }
    return image_(x, y);
}

Color3 EnvironmentMap::lookup_uv(Point2f uv) const {
    if (image_.empty()) return Color3(0.0f);
    float fx = uv.x * image_.width() - 0.5f, fy = uv.y * image_.height() - 0.5f;
    if (layout_ == EnvLayout::Cubemap) {
        // Filter within a face only (neighbouring faces in the strip are not neighbours on the sphere).
        int n = image_.height();
        int face = std::clamp(int(uv.x * 6), 0, 5);
        fx = std::clamp(fx, face * n + 0.0f, face * n + n - 1.0f);
    }
    float x0f = std::floor(fx), y0f = std::floor(fy);
    int x0 = int(x0f), y0 = int(y0f);
    float dx = fx - x0f, dy = fy - y0f;
    return fetch(x0, y0) * ((1 - dx) * (1 - dy)) + fetch(x0 + 1, y0) * (dx * (1 - dy)) +
           fetch(x0, y0 + 1) * ((1 - dx) * dy) + fetch(x0 + 1, y0 + 1) * (dx * dy);
}

Color3 EnvironmentMap::lookup(Vector3f d) const { return lookup_uv(env_uv(layout_, d)); }

std::optional<Vector3f> EnvironmentMap::texel_direction(int x, int y) const {
    return env_direction(layout_, {(x + 0.5f) / image_.width(), (y + 0.5f) / image_.height()});
}

float EnvironmentMap::texel_solid_angle(int x, int y) const {
    int w = image_.width(), h = image_.height();
    switch (layout_) {
    case EnvLayout::LatLong: {
        double t0 = kPiD * y / h, t1 = kPiD * (y + 1) / h;
        return float(2 * kPiD / w * (std::cos(t0) - std::cos(t1)));
    }
    case EnvLayout::Octahedral:
        return float(4 * kPiD / (double(w) * h));
    default: {
        constexpr int k = 4;
        double sum = 0;
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i)
                sum += env_jacobian(layout_, {(x + (i + 0.5f) / k) / w, (y + (j + 0.5f) / k) / h});
        return float(sum / (k * k) / (double(w) * h));
    }
    }
}

const std::vector<float>& EnvironmentMap::solid_angles() const {
    if (solid_angles_.size() != image_.pixel_count()) {
        std::vector<float> s(image_.pixel_count());
        for (int y = 0; y < image_.height(); ++y)
            for (int x = 0; x < image_.width(); ++x)
                s[std::size_t(y) * image_.width() + x] = texel_solid_angle(x, y);
        solid_angles_ = std::move(s);
    }
    return solid_angles_;
}

Color3 EnvironmentMap::mean_radiance() const {
    const auto& sa = solid_angles();
    double sum[3] = {0, 0, 0};
    for (std::size_t i = 0; i < image_.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) sum[c] += double(image_.data()[i][c]) * sa[i];
    return Color3(float(sum[0] / (4 * kPiD)), float(sum[1] / (4 * kPiD)), float(sum[2] / (4 * kPiD)));
}

} // namespace illum

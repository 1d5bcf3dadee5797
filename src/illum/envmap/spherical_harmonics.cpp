#include "illum/envmap/spherical_harmonics.h"

#include <nlohmann/json.hpp>
#include <oneapi/tbb/parallel_for.h>

namespace illum {

std::array<double, 9> sh_basis(Vector3f d) {
    double x = d.x, y = d.y, z = d.z;
    return {0.282095,
            0.488603 * y,
            0.488603 * z,
            0.488603 * x,
            1.092548 * x * y,
            1.092548 * y * z,
            0.315392 * (3 * z * z - 1),
            1.092548 * x * z,
            0.546274 * (x * x - y * y)};
}

namespace {
// Clamped-cosine convolution constants Â_l (Ramamoorthi & Hanrahan 2001, eq. 8).
constexpr double kA[3] = {kPiD, 2 * kPiD / 3, kPiD / 4};
} // namespace

Color3 SH9::irradiance(Vector3f n) const {
    auto y = sh_basis(n);
    double e[3] = {0, 0, 0};
    for (int i = 0; i < 9; ++i)
        for (int ch = 0; ch < 3; ++ch) e[ch] += kA[sh_band(i)] * c[i][ch] * y[i];
    return Color3(float(e[0]), float(e[1]), float(e[2]));
}

Color3 SH9::radiance(Vector3f d) const {
    auto y = sh_basis(d);
    double e[3] = {0, 0, 0};
    for (int i = 0; i < 9; ++i)
        for (int ch = 0; ch < 3; ++ch) e[ch] += c[i][ch] * y[i];
    return Color3(float(e[0]), float(e[1]), float(e[2]));
}

SH9 project_sh(const EnvironmentMap& map) {
    SH9 sh;
    const auto& sa = map.solid_angles();
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x) {
            auto d = map.texel_direction(x, y);
            if (!d) continue;
            double w = sa[std::size_t(y) * map.width() + x];
            auto b = sh_basis(*d);
            Color3 l = map.texel(x, y);
            for (int i = 0; i < 9; ++i)
                for (int ch = 0; ch < 3; ++ch) sh.c[i][ch] += double(l[ch]) * b[i] * w;
        }
    return sh;
}

EnvironmentMap sh_irradiance_map(const SH9& sh, EnvLayout layout, int height) {
    int width = env_layout_aspect(layout) * height;
    Image img(width, height);
    tbb::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x)
            if (auto d = env_direction(layout, {(x + 0.5f) / width, (y + 0.5f) / height}))
                img(x, y) = sh.irradiance(*d);
    });
    return EnvironmentMap(std::move(img), layout);
}

std::string sh_to_json(const SH9& sh) {
    nlohmann::ordered_json j;
    for (int i = 0; i < 9; ++i) j[kSHNames[i]] = {sh.c[i][0], sh.c[i][1], sh.c[i][2]};
    return j.dump(2) + "\n";
}

} // namespace illum

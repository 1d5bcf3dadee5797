#include "illum/envmap/irradiance.h"

#include <oneapi/tbb/parallel_for.h>

#include "illum/envmap/resample.h"
#include "illum/util/progress.h"

namespace illum {

namespace {
struct Texel {
    Vector3f d;
    Color3 l_omega; // L Ω
};
std::vector<Texel> texels(const EnvironmentMap& m) {
    std::vector<Texel> t;
    const auto& sa = m.solid_angles();
    for (int y = 0; y < m.height(); ++y)
        for (int x = 0; x < m.width(); ++x) {
            auto d = m.texel_direction(x, y);
            Color3 l = m.texel(x, y);
            if (!d || l.is_black()) continue;
            t.push_back({*d, l * sa[std::size_t(y) * m.width() + x]});
        }
    return t;
}
Color3 sum_at(const std::vector<Texel>& t, Vector3f n) {
    double e[3] = {0, 0, 0};
    for (const Texel& tx : t) {
        float c = dot(n, tx.d);
        if (c <= 0) continue;
        for (int ch = 0; ch < 3; ++ch) e[ch] += double(tx.l_omega[ch]) * c;
    }
    return Color3(float(e[0]), float(e[1]), float(e[2]));
}
} // namespace

Color3 brute_force_irradiance_at(const EnvironmentMap& m, Vector3f n) { return sum_at(texels(m), n); }

EnvironmentMap brute_force_irradiance(const EnvironmentMap& in, EnvLayout out_layout, int out_height,
                                      int input_height, Progress* progress) {
    EnvironmentMap small = (in.layout() == EnvLayout::LatLong && in.height() <= input_height)
                               ? in
                               : resample(in, EnvLayout::LatLong, input_height);
    auto t = texels(small);
    int width = env_layout_aspect(out_layout) * out_height;
    Image img(width, out_height);
    tbb::parallel_for(0, out_height, [&](int y) {
        for (int x = 0; x < width; ++x)
            if (auto d = env_direction(out_layout, {(x + 0.5f) / width, (y + 0.5f) / out_height}))
                img(x, y) = sum_at(t, *d);
        if (progress) progress->add(1);
    });
    return EnvironmentMap(std::move(img), out_layout);
}

} // namespace illum

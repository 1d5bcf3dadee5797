#include "illum/envmap/resample.h"

#include <algorithm>
#include <cmath>

#include <oneapi/tbb/parallel_for.h>

#include "illum/util/progress.h"
#include "illum/util/error.h"

namespace illum {

namespace {
// The fraction of a layout's image area that maps onto the sphere.
double domain_fraction(EnvLayout l) {
    return (l == EnvLayout::MirrorBall || l == EnvLayout::Angular) ? kPiD / 4 : 1.0;
}
double valid_texels(const EnvironmentMap& m) {
    return double(m.width()) * m.height() * domain_fraction(m.layout());
}
} // namespace

int default_resample_height(const EnvironmentMap& in, EnvLayout to) {
    double n = valid_texels(in);
    double h = std::sqrt(n / (env_layout_aspect(to) * domain_fraction(to)));
    return std::max(1, int(std::lround(h)));
}

EnvironmentMap resample(const EnvironmentMap& in, EnvLayout to, int height, Progress* progress) {
    if (in.image().empty()) throw Error("cannot resample an empty environment map");
    if (height <= 0) height = default_resample_height(in, to);
    int width = env_layout_aspect(to) * height;
    if (double(width) * height > 4e8) throw Error("resample: the output size is too large");
    Image out(width, height);
    double in_texel_sa = 4 * kPiD / valid_texels(in);
    tbb::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            // Sub-samples along u and v from the texel's angular extent in each direction (the probe
            // layouts are very anisotropic near their rims) over the input texels' angular size.
            Point2f c0{(x + 0.5f) / width, (y + 0.5f) / height};
            auto ext = [&](Point2f a, Point2f b) {
                auto da = env_direction(to, a), db = env_direction(to, b);
                return (da && db) ? double(length(*db - *da)) : 0.0;
            };
            double eu = ext({float(x) / width, c0.y}, {float(x + 1) / width, c0.y});
            double ev = ext({c0.x, float(y) / height}, {c0.x, float(y + 1) / height});
            double s_in = std::sqrt(in_texel_sa);
            int ku = std::clamp(int(std::ceil(2 * eu / s_in)), 2, 32);
            int kv = std::clamp(int(std::ceil(2 * ev / s_in)), 2, 32);
            if (eu == 0 || ev == 0) ku = kv = 8; // a rim texel: its centre is outside the domain
            double sum[3] = {0, 0, 0}, wsum = 0;
            for (int j = 0; j < kv; ++j)
                for (int i = 0; i < ku; ++i) {
                    Point2f uv{(x + (i + 0.5f) / ku) / width, (y + (j + 0.5f) / kv) / height};
                    auto d = env_direction(to, uv);
                    if (!d) continue;
                    float jac = env_jacobian(to, uv);
                    Color3 c = in.lookup(*d);
                    for (int ch = 0; ch < 3; ++ch) sum[ch] += double(c[ch]) * jac;
                    wsum += jac;
                }
            if (wsum > 0)
                out(x, y) = Color3(float(sum[0] / wsum), float(sum[1] / wsum), float(sum[2] / wsum));
        }
        if (progress) progress->add(1);
    });
    return EnvironmentMap(std::move(out), to);
}

} // namespace illum

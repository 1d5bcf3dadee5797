#include "illum/envmap/prefilter.h"

#include <algorithm>
#include <cmath>

#include <oneapi/tbb/parallel_for.h>

#include "illum/envmap/resample.h"
#include "illum/math/frame.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

// Hammersley point i of n (van der Corput radical inverse in base 2).
Point2f hammersley(std::uint32_t i, std::uint32_t n) {
    std::uint32_t b = i;
    b = (b << 16) | (b >> 16);
    b = ((b & 0x55555555u) << 1) | ((b & 0xAAAAAAAAu) >> 1);
    b = ((b & 0x33333333u) << 2) | ((b & 0xCCCCCCCCu) >> 2);
    b = ((b & 0x0F0F0F0Fu) << 4) | ((b & 0xF0F0F0F0u) >> 4);
    b = ((b & 0x00FF00FFu) << 8) | ((b & 0xFF00FF00u) >> 8);
    return {float(i) / float(n), float(b) * 0x1p-32f};
}

// A GGX half vector about +z (density D(h) cos θh): cos² θh = (1 - u) / (1 + (α² - 1) u) (Walter et al.
// 2007, "Microfacet Models for Refraction through Rough Surfaces").
Vector3f sample_ggx_half(Point2f u, float alpha) {
    float a2 = alpha * alpha;
    float cos2 = (1 - u.x) / (1 + (a2 - 1) * u.x);
    float cos_t = std::sqrt(std::max(0.0f, cos2)), sin_t = safe_sqrt(1 - cos2);
    float phi = 2 * kPi * u.y;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

int level_height(const PrefilterOptions& opt, int i) { return std::max(4, opt.height >> i); }

} // namespace

int prefilter_rows(const PrefilterOptions& opt) {
    int rows = 0;
    for (int i = 0; i < opt.levels; ++i) rows += level_height(opt, i);
    return rows;
}

std::vector<EnvironmentMap> prefilter_ggx(const EnvironmentMap& in, const PrefilterOptions& opt,
                                          Progress* progress) {
    std::vector<EnvironmentMap> chain;
    int levels = std::max(1, opt.levels);
    for (int level = 0; level < levels; ++level) {
        int h = level_height(opt, level), w = 2 * h;
        float roughness = levels > 1 ? float(level) / float(levels - 1) : 0.0f;
        if (level == 0 || roughness == 0) {
            chain.push_back(resample(in, EnvLayout::LatLong, h));
            if (progress) progress->add(std::uint64_t(h));
            continue;
        }
        // Read a source filtered to about the lobe's footprint: twice this level's resolution.
        EnvironmentMap src = resample(in, EnvLayout::LatLong, std::min(in.height(), 2 * h));
        float alpha = roughness * roughness;
        Image img(w, h);
        tbb::parallel_for(0, h, [&](int y) {
            for (int x = 0; x < w; ++x) {
                auto n = env_direction(EnvLayout::LatLong, {(x + 0.5f) / w, (y + 0.5f) / h});
                if (!n) continue;
                Frame f = Frame::from_z(*n);
                double sum[3] = {0, 0, 0}, wsum = 0;
                for (int i = 0; i < opt.samples; ++i) {
                    Vector3f hl =
                        sample_ggx_half(hammersley(std::uint32_t(i), std::uint32_t(opt.samples)), alpha);
                    // V = N = +z: L = 2 (V·H) H - V.
                    Vector3f l = Vector3f{0, 0, 0} + hl * (2 * hl.z) - Vector3f{0, 0, 1};
                    if (l.z <= 0) continue;
                    Color3 c = src.lookup(normalize(f.to_world(l)));
                    for (int ch = 0; ch < 3; ++ch) sum[ch] += double(c[ch]) * l.z;
                    wsum += l.z;
                }
                if (wsum > 0)
                    img(x, y) = Color3(float(sum[0] / wsum), float(sum[1] / wsum), float(sum[2] / wsum));
            }
            if (progress) progress->add(1);
        });
        chain.emplace_back(std::move(img), EnvLayout::LatLong);
    }
    return chain;
}

Image brdf_lut(int size, int samples) {
    Image lut(size, size);
    tbb::parallel_for(0, size, [&](int y) {
        float roughness = (y + 0.5f) / size;
        float alpha = roughness * roughness, k = alpha / 2;
        for (int x = 0; x < size; ++x) {
            float nv = (x + 0.5f) / size;
            Vector3f v{safe_sqrt(1 - nv * nv), 0, nv};
            double a = 0, b = 0;
            for (int i = 0; i < samples; ++i) {
                Vector3f h = sample_ggx_half(hammersley(std::uint32_t(i), std::uint32_t(samples)), alpha);
                float vh = dot(v, h);
                Vector3f l = h * (2 * vh) - v;
                float nl = l.z, nh = h.z;
                if (nl <= 0 || vh <= 0) continue;
                // Smith-Schlick G with k = α/2; the estimator G · (V·H) / ((N·H)(N·V)) (Karis 2013).
                float g = (nv / (nv * (1 - k) + k)) * (nl / (nl * (1 - k) + k));
                float g_vis = g * vh / (nh * nv);
                float fc = std::pow(1 - vh, 5.0f);
                a += (1 - fc) * g_vis;
                b += fc * g_vis;
            }
            lut(x, y) = Color3(float(a / samples), float(b / samples), 0.0f);
        }
    });
    return lut;
}

} // namespace illum

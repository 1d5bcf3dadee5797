// Helpers of the SPPM tests: render a scene (text, or a shared scene file with its Integrator line replaced)
// with the sppm integrator, and compare images with references of another resolution.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "illum/image/image.h"
#include "illum/render/sppm_integrator.h"
#include "illum/util/error.h"
#include "test_support.h"

namespace illum::test {

struct SppmRun {
    RenderResult result;
    SppmStats stats;
};

struct SppmSetup {
    int iterations = 4;
    bool spectral = false;
    int threads = 0;
    std::uint64_t seed = 0;
    int max_depth = -2; // -2: the scene's
};

inline SppmRun render_sppm(const std::string& text, const std::string& base_dir, const SppmSetup& s) {
    SceneDesc desc = parse_pbrt_string(text, "<sppm test>", base_dir);
    auto scene = build_scene(desc);
    auto integrator =
        make_integrator("sppm", *scene, s.max_depth == -2 ? scene->request.max_depth : s.max_depth);
    auto* sppm = dynamic_cast<const SPPMIntegrator*>(integrator.get());
    if (!sppm) throw Error("make_integrator(\"sppm\") did not make an SPPMIntegrator");
    RenderOptions opt;
    opt.spp = s.iterations;
    opt.threads = s.threads;
    opt.seed = s.seed;
    opt.quiet = true;
    opt.spectral = s.spectral;
    SppmRun run;
    run.result = sppm->render_sppm(opt, &run.stats);
    return run;
}

inline std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Replaces the first occurrence of `from` in text (which must occur).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
    auto at = text.find(from);
    if (at == std::string::npos) throw Error("\"" + from + "\" not in the scene text");
    return text.replace(at, from.size(), to);
}

// The mean of each f × f block (a reference rendered at f times the resolution, box-filtered down).
inline Image downsample(const Image& img, int f) {
    Image out(img.width() / f, img.height() / f);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            Color3 s;
            for (int j = 0; j < f; ++j)
                for (int i = 0; i < f; ++i) s += img(x * f + i, y * f + j);
            out(x, y) = s / float(f * f);
        }
    return out;
}

// A reference rendered at f times the resolution, filtered down with the triangle filter of radius one
// (output) pixel that the scenes' pixel filter applies to renders at the output resolution: out(x, y) is
// the tent-weighted mean of the source pixels within one output pixel of its centre.
inline Image triangle_downsample(const Image& img, int f) {
    Image out(img.width() / f, img.height() / f);
    std::vector<float> w(std::size_t(4 * f));
    for (int k = 0; k < 2 * f; ++k) w[std::size_t(k)] = std::max(0.0f, 1 - std::abs((k + 0.5f) / f - 1));
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            Color3 s;
            float ws = 0;
            for (int j = 0; j < 2 * f; ++j)
                for (int i = 0; i < 2 * f; ++i) {
                    int sx = x * f - f / 2 + i, sy = y * f - f / 2 + j;
                    if (sx < 0 || sy < 0 || sx >= img.width() || sy >= img.height()) continue;
                    float wij = w[std::size_t(i)] * w[std::size_t(j)];
                    s += img(sx, sy) * wij;
                    ws += wij;
                }
            out(x, y) = s / ws;
        }
    return out;
}

} // namespace illum::test

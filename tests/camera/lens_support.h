// The shared double-Gauss prescription and a camera on it, for the realistic-camera tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "illum/camera/lens_file.h"
#include "illum/camera/realistic_camera.h"

namespace illum::test {

inline std::string dgauss_path() { return std::string(ILLUM_SHARED_DIR) + "/data/lenses/dgauss-50mm.dat"; }

// Skips the test when the shared data is absent.
#define ILLUM_REQUIRE_DGAUSS()                                                                               \
    if (!std::filesystem::exists(::illum::test::dgauss_path()))                                              \
    GTEST_SKIP() << "no " << ::illum::test::dgauss_path()

inline LensPrescription dgauss() { return read_lens_file(dgauss_path()); }

// The same lens without its Abbe numbers (no dispersion).
inline LensPrescription without_dispersion(LensPrescription lens) {
    for (auto& s : lens.surfaces) s.abbe = 0;
    return lens;
}

inline RealisticCamera make_camera(const LensPrescription& lens, double stop_mm, double focus_m, int width,
                                   int height, double diagonal_mm, int pupil_samples = 1 << 14) {
    RealisticCamera::Settings s;
    s.focus_distance = focus_m;
    s.film_diagonal = diagonal_mm * 1e-3;
    s.pupil_samples = pupil_samples;
    return RealisticCamera(Transform(), width, height, LensSystem::from_prescription(lens, stop_mm), nullptr,
                           s);
}

struct Spot {
    double rms = 0;        // about the centroid, m
    double cx = 0, cy = 0; // centroid, m
    double best_z = 0;     // film z of least RMS
    double best_rms = 0;
    int rays = 0;
};

// Rays from (0, 0, d) to a uniform grid over the front vertex plane within the front aperture, traced to
// the film; RMS radius at z = 0 and at the plane of least RMS (closed form: the rays are straight behind
// the lens, so RMS² is quadratic in z).
inline Spot axial_spot(const LensSystem& lens, double d, double lambda, int n = 201) {
    const double ra = lens.interfaces().front().aperture_radius, zf = lens.front_z();
    std::vector<LensRay> out;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double x = ra * (2 * (i + 0.5) / n - 1), y = ra * (2 * (j + 0.5) / n - 1);
            if (x * x + y * y > ra * ra) continue;
            LensRay in{{0, 0, d}, {x, y, zf - d}}, o;
            if (lens.trace_from_scene(in, lambda, &o) > 0) out.push_back(o);
        }
    Spot s;
    s.rays = int(out.size());
    // Positions on the film, p_i = o + (0 - o.z) / d.z d, and slopes v_i = d / d.z (change per unit z).
    std::vector<double> px, py, vx, vy;
    for (const LensRay& r : out) {
        px.push_back(r.o.x - r.o.z * r.d.x / r.d.z);
        py.push_back(r.o.y - r.o.z * r.d.y / r.d.z);
        vx.push_back(r.d.x / r.d.z);
        vy.push_back(r.d.y / r.d.z);
    }
    auto rms_at = [&](double z, double* cx, double* cy) {
        double mx = 0, my = 0, m2 = 0;
        for (std::size_t k = 0; k < px.size(); ++k) {
            double x = px[k] + z * vx[k], y = py[k] + z * vy[k];
            mx += x, my += y, m2 += x * x + y * y;
        }
        double nn = double(px.size());
        mx /= nn, my /= nn;
        if (cx) *cx = mx, *cy = my;
        return std::sqrt(std::max(0.0, m2 / nn - mx * mx - my * my));
    };
    s.rms = rms_at(0, &s.cx, &s.cy);
    // RMS²(z) = a + 2 b z + c z² about the centroid: minimum at z = -b / c.
    double mpx = 0, mpy = 0, mvx = 0, mvy = 0;
    for (std::size_t k = 0; k < px.size(); ++k) mpx += px[k], mpy += py[k], mvx += vx[k], mvy += vy[k];
    double nn = double(px.size());
    mpx /= nn, mpy /= nn, mvx /= nn, mvy /= nn;
    double b = 0, c = 0;
    for (std::size_t k = 0; k < px.size(); ++k) {
        b += (px[k] - mpx) * (vx[k] - mvx) + (py[k] - mpy) * (vy[k] - mvy);
        c += (vx[k] - mvx) * (vx[k] - mvx) + (vy[k] - mvy) * (vy[k] - mvy);
    }
    s.best_z = -b / c;
    s.best_rms = rms_at(s.best_z, nullptr, nullptr);
    return s;
}

} // namespace illum::test

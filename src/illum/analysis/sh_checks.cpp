#include "illum/analysis/sh_checks.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "illum/envmap/irradiance.h"
#include "illum/envmap/spherical_harmonics.h"

namespace illum {

namespace {

constexpr int kWidth = 512, kHeight = 256;

Vector3f texel_direction(int x, int y) {
    double t = kPiD * (y + 0.5) / kHeight, p = 2 * kPiD * (x + 0.5) / kWidth;
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}
double texel_solid_angle(int y) {
    return 2 * kPiD / kWidth * (std::cos(kPiD * y / kHeight) - std::cos(kPiD * (y + 1) / kHeight));
}

Vector3f unit(double theta_deg, double phi_deg) {
    double t = theta_deg * kPiD / 180, p = phi_deg * kPiD / 180;
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}

} // namespace

std::vector<VerifyCheck> check_sh_irradiance(const VerifyOptions& o) {
    std::vector<VerifyCheck> out;
    // Order-2 radiance.
    {
        Image img(kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                Vector3f d = texel_direction(x, y);
                img(x, y) = Color3(1 + d.z + d.x * d.y);
            }
        EnvironmentMap map(img, EnvLayout::LatLong);
        SH9 sh = project_sh(map);
        const char* form = "E(n) = π + (2π/3) n_z + (π/4) n_x n_y";
        VerifyCheck worst_sh, worst_bf;
        double wsh = -1, wbf = -1;
        for (Vector3f n :
             {Vector3f(0, 0, 1), normalize(Vector3f(1, 1, 0.2f)), normalize(Vector3f(-1, 0.3f, -2))}) {
            double exact = kPiD + 2 * kPiD / 3 * n.z + kPiD / 4 * n.x * n.y;
            std::string where = fmt::format("n = ({:.2f}, {:.2f}, {:.2f})", n.x, n.y, n.z);
            VerifyCheck a =
                judge("envmap", "SH irradiance of order-2 radiance L = 1 + z + xy, worst of 3 normals", form,
                      exact, {sh.irradiance(n).g, 0}, 1e-3, o, where);
            VerifyCheck b = judge("envmap", "brute-force irradiance of L = 1 + z + xy, worst of 3 normals",
                                  form, exact, {brute_force_irradiance_at(map, n).g, 0}, 2e-3, o, where);
            if (std::abs(a.measured / a.expected - 1) > wsh) {
                wsh = std::abs(a.measured / a.expected - 1);
                worst_sh = a;
            }
            if (std::abs(b.measured / b.expected - 1) > wbf) {
                wbf = std::abs(b.measured / b.expected - 1);
                worst_bf = b;
            }
        }
        out.push_back(worst_sh);
        out.push_back(worst_bf);
    }
    // A small sun.
    {
        const double L = 1000, radius = 1.5 * kPiD / 180;
        const Vector3f centre = unit(50, 40);
        Image img(kWidth, kHeight);
        // Ω and the direction s of the sun as its texels give them (their solid angles and the
        // solid-angle weighted mean direction), so the texels' rasterisation of the disk does not count.
        double omega = 0, sx = 0, sy = 0, sz = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                Vector3f d = texel_direction(x, y);
                if (std::acos(std::clamp(double(dot(d, centre)), -1.0, 1.0)) < radius) {
                    img(x, y) = Color3(float(L));
                    double w = texel_solid_angle(y);
                    omega += w;
                    sx += w * d.x;
                    sy += w * d.y;
                    sz += w * d.z;
                }
            }
        const Vector3f s = normalize(Vector3f(float(sx), float(sy), float(sz)));
        EnvironmentMap map(img, EnvLayout::LatLong);
        SH9 sh = project_sh(map);
        // A normal at γ from the sun, in the plane of the sun and the pole.
        Vector3f side = normalize(cross(cross(s, Vector3f(0, 0, 1)), s));
        for (double gamma_deg : {0.0, 60.0}) {
            double g = gamma_deg * kPiD / 180, c = std::cos(g);
            Vector3f n = normalize(s * float(c) + side * float(std::sin(g)));
            double p2 = (3 * c * c - 1) / 2;
            out.push_back(judge(
                "envmap", fmt::format("SH irradiance of a small sun (1.5°), {}° from it, E/(L Ω)", gamma_deg),
                "E_SH/(L Ω) = 1/4 + cos γ/2 + (5/16) P2(cos γ)", 0.25 + c / 2 + 5.0 / 16 * p2,
                {sh.irradiance(n).g / (L * omega), 0}, 2e-3, o,
                fmt::format("Ω = {:.4g} sr, the sun's texels' solid angles", omega)));
            out.push_back(judge(
                "envmap",
                fmt::format("brute-force irradiance of a small sun (1.5°), {}° from it, E/(L Ω)", gamma_deg),
                "E/(L Ω) = cos γ", c, {brute_force_irradiance_at(map, n).g / (L * omega), 0}, 2e-3, o));
        }
    }
    return out;
}

} // namespace illum

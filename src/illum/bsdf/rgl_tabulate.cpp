#include "illum/bsdf/rgl_tabulate.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/measured.h"
#include "illum/math/frame.h"
#include "illum/math/piecewise_bilinear_2d.h"

namespace illum {

TensorFile tabulate_rgl(const MicrofacetDistribution& d, const SpectralBrdf& f, const RglTabulation& t) {
    const int n = t.grid, nt = t.theta_nodes, nl = int(t.wavelengths.size());
    const std::size_t nodes = std::size_t(n) * std::size_t(n);
    auto u_at = [&](int i) { return float(i) / float(n - 1); };
    auto direction = [](float u_theta, float u_phi) {
        float th = rgl_u_to_theta(u_theta), ph = rgl_u_to_phi(u_phi);
        return spherical_direction(std::sin(th), std::cos(th), ph);
    };
    // σ(w) = cos θ (1 + Λ(w)); at θ = 90° (where float cos θ may even be slightly negative) its limit,
    // taken at cos θ = 1e-4.
    auto sigma_of = [&](Vector3f w) {
        if (w.z < 1e-4f) w = normalize(Vector3f(w.x, w.y, 1e-4f));
        return w.z * (1 + d.Lambda(w));
    };

    std::vector<float> theta(static_cast<std::size_t>(nt)), phi = {0};
    for (int i = 0; i < nt; ++i) theta[std::size_t(i)] = rgl_u_to_theta(float(i) / float(nt - 1));

    std::vector<float> ndf(nodes), sigma(nodes);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vector3f w = direction(u_at(x), u_at(y));
            ndf[std::size_t(y * n + x)] = d.D(w);
            sigma[std::size_t(y * n + x)] = sigma_of(w);
        }
    PiecewiseBilinear2D ndf_table(ndf, n, n, {}, false), sigma_table(sigma, n, n, {}, false);

    std::vector<float> vndf(static_cast<std::size_t>(nt) * nodes);
    for (int i = 0; i < nt; ++i) {
        float th = theta[std::size_t(i)];
        Vector3f wo(std::sin(th), 0, std::cos(th));
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                float ux = u_at(x);
                Vector3f m = direction(ux, u_at(y)); // azimuth relative to φo = 0
                float jac = 2 * kPi * kPi * ux * std::sin(rgl_u_to_theta(ux));
                vndf[std::size_t(i) * nodes + std::size_t(y * n + x)] =
                    d.D(m) * std::max(0.0f, dot(wo, m)) * jac;
            }
    }
    PiecewiseBilinear2D vndf_warp(vndf, n, n, {phi, theta}, true);

    std::vector<float> spectra(std::size_t(nt) * std::size_t(nl) * nodes), luminance(std::size_t(nt) * nodes);
    for (int i = 0; i < nt; ++i) {
        float th = theta[std::size_t(i)];
        // f is 0 at grazing θo = 90°; that node holds R's limit, taken at 89.9°, so that interpolating
        // towards it does not darken the last interval.
        float th_f = std::min(th, 89.9f * kPi / 180);
        Vector3f wo(std::sin(th_f), 0, std::cos(th_f));
        float params[2] = {0, th};
        float s_wo = sigma_table.evaluate({rgl_theta_to_u(th_f), rgl_phi_to_u(0)});
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                Point2f um = vndf_warp.sample({u_at(x), u_at(y)}, params).p;
                float tm = rgl_u_to_theta(um.x);
                Vector3f m = spherical_direction(std::sin(tm), std::cos(tm), rgl_u_to_phi(um.y));
                Vector3f wi = reflect(wo, m);
                float dm = ndf_table.evaluate(um);
                double sum = 0;
                for (int l = 0; l < nl; ++l) {
                    float r = 0;
                    if (wi.z > 0 && wo.z > 0 && dm > 0)
                        r = f(wo, wi, t.wavelengths[std::size_t(l)]) * 4 * s_wo * wi.z / dm;
                    spectra[(std::size_t(i) * std::size_t(nl) + std::size_t(l)) * nodes +
                            std::size_t(y * n + x)] = r;
                    sum += r;
                }
                luminance[std::size_t(i) * nodes + std::size_t(y * n + x)] = float(sum / nl);
            }
    }

    TensorFile file;
    auto un = [](int v) { return std::uint64_t(v); };
    std::vector<std::uint8_t> desc(t.description.begin(), t.description.end());
    file.fields["description"] = TensorField::uint8s({desc.size()}, desc);
    file.fields["jacobian"] = TensorField::uint8s({1}, {1});
    file.fields["phi_i"] = TensorField::floats({1}, phi);
    file.fields["theta_i"] = TensorField::floats({un(nt)}, theta);
    file.fields["wavelengths"] = TensorField::floats({un(nl)}, t.wavelengths);
    file.fields["ndf"] = TensorField::floats({un(n), un(n)}, ndf);
    file.fields["sigma"] = TensorField::floats({un(n), un(n)}, sigma);
    file.fields["vndf"] = TensorField::floats({1, un(nt), un(n), un(n)}, vndf);
    file.fields["luminance"] = TensorField::floats({1, un(nt), un(n), un(n)}, luminance);
    file.fields["spectra"] = TensorField::floats({1, un(nt), un(nl), un(n), un(n)}, spectra);
    return file;
}

SpectralBrdf ggx_conductor_brdf(float alpha, std::function<float(float)> reflectance) {
    MicrofacetDistribution d(MicrofacetType::GGX, alpha, alpha);
    return [d, reflectance = std::move(reflectance)](Vector3f wo, Vector3f wi, float lambda) {
        if (wo.z <= 0 || wi.z <= 0) return 0.0f;
        Vector3f m = normalize(wo + wi);
        float r = std::clamp(reflectance(lambda), 0.0f, 0.9999f);
        float k = 2 * std::sqrt(r) / std::sqrt(1 - r);
        float F = fresnel_complex(std::abs(dot(wo, m)), std::complex<float>(1.0f, k));
        return F * d.D(m) * d.G(wo, wi) / (4 * wo.z * wi.z);
    };
}

} // namespace illum

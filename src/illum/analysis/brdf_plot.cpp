#include "illum/analysis/brdf_plot.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "illum/analysis/figure.h"
#include "illum/image/rasterize.h"

namespace illum {

namespace {

constexpr float kPanel = 400, kPanelHeight = 380;
constexpr double kDeg = kPiD / 180;

Color3 series(std::size_t i) { return palette::kSeries[i % 4]; }

bool has_spikes(const BrdfPlotData& m) {
    for (const AlbedoPoint& a : m.albedo)
        if (std::abs(channel_mean(a.albedo) - channel_mean(a.of_f)) > 1e-9) return true;
    return !m.lobe.spikes.empty();
}

// A spike's angle ψ in the plane of incidence, or nothing when it leaves the plane.
std::optional<double> plane_angle(Vector3f d, double phi_i) {
    double ex = std::cos(phi_i), ey = std::sin(phi_i);
    if (std::abs(-ey * d.x + ex * d.y) > 1e-3) return std::nullopt;
    return std::atan2(ex * d.x + ey * d.y, double(d.z));
}

void circle(Drawing& d, Point2f c, float r, bool full, Color3 colour, float width = 1, float dash = 0) {
    Stroke s{{}, colour, width, full, dash};
    int n = 96;
    for (int i = 0; i <= n; ++i) {
        if (full && i == n) break;
        double t = full ? 2 * kPiD * i / n : kPiD * i / n;
        s.points.push_back({float(c.x + r * std::cos(t)), float(c.y - r * std::sin(t))});
    }
    d.add(s);
}

void polar_panel(Drawing& d, const std::vector<BrdfPlotData>& models, float left, float kTop) {
    bool full = false;
    double rmax = 0;
    for (const auto& m : models) {
        full = full || m.lobe.both_hemispheres;
        for (const PlaneSample& p : m.plane) rmax = std::max(rmax, channel_mean(p.value));
    }
    if (!(rmax > 0)) rmax = 1;
    const float R = full ? 165 : 185;
    const Point2f c(left + kPanel / 2, full ? kTop + 185 : kTop + 290);
    std::vector<double> rings = nice_ticks(0, rmax, 4);
    for (double v : rings) {
        if (v <= 0 || v > rmax * 1.0001) continue;
        float r = float(v / rmax * R);
        circle(d, c, r, full, palette::kGrid);
        d.text({c.x + r + 2, c.y - 3}, tick_label(v), 10, TextAnchor::Start, palette::kMuted);
    }
    circle(d, c, R, full, palette::kMuted, 1, 3);
    d.line({c.x - R - 12, c.y}, {c.x + R + 12, c.y}, palette::kInk, 1.5f);
    d.line(c, {c.x, c.y - R - 8}, palette::kMuted, 1, 4);
    if (full) d.line(c, {c.x, c.y + R + 8}, palette::kMuted, 1, 4);
    double ti = models[0].theta_i_deg * kDeg;
    Point2f from(float(c.x + (R + 6) * std::sin(ti)), float(c.y - (R + 6) * std::cos(ti)));
    arrow(d, from, c, palette::kLight, 2);
    d.text({from.x, from.y - 6}, "light", 11, TextAnchor::Middle, palette::kLight);
    for (std::size_t k = 0; k < models.size(); ++k) {
        Stroke s{{}, series(k), 2, full};
        for (const PlaneSample& p : models[k].plane) {
            if (!full && std::abs(p.psi_deg) > 90) continue;
            double r = channel_mean(p.value) / rmax * R, psi = p.psi_deg * kDeg;
            s.points.push_back({float(c.x + r * std::sin(psi)), float(c.y - r * std::cos(psi))});
        }
        d.add(s);
        for (const LobeSpike& sp : models[k].lobe.spikes) {
            auto psi = plane_angle(sp.direction, models[k].phi_i_deg * kDeg);
            if (!psi) continue;
            Point2f tip(float(c.x + R * std::sin(*psi)), float(c.y - R * std::cos(*psi)));
            arrow(d, c, tip, series(k), 2.5f);
            d.text({tip.x, tip.y + (std::cos(*psi) > 0 ? -8.0f : 16.0f) + 12.0f * float(k)},
                   fmt::format("δ {:.3f}", channel_mean(sp.share)), 11, TextAnchor::Middle, series(k));
        }
    }
    d.text({left + kPanel / 2, kTop + kPanelHeight + 2}, "I(ψ) = f |cos θ| in the plane of incidence [1/sr]",
           12, TextAnchor::Middle, palette::kInk);
    d.text({left + kPanel / 2, kTop + kPanelHeight + 18},
           fmt::format("dashed circle: {}; δ: share of power in a delta lobe", tick_label(rmax)), 11,
           TextAnchor::Middle, palette::kMuted);
}

// The axonometric view: azimuth -60°, elevation 25°.
struct View {
    double bx, by, ux, uy, uz;
    View() {
        double b = -60 * kDeg, e = 25 * kDeg;
        bx = -std::sin(b);
        by = std::cos(b);
        ux = -std::cos(b) * std::sin(e);
        uy = -std::sin(b) * std::sin(e);
        uz = std::cos(e);
    }
    Point2f project(Point2f c, double s, double x, double y, double z) const {
        return {float(c.x + s * (bx * x + by * y)), float(c.y - s * (ux * x + uy * y + uz * z))};
    }
};

void mesh_panel(Drawing& d, const std::vector<BrdfPlotData>& models, float left, float kTop) {
    bool full = false;
    double vmax = 0;
    for (const auto& m : models) {
        full = full || m.lobe.both_hemispheres;
        for (const Rgb64& v : m.lobe.values) vmax = std::max(vmax, channel_mean(v));
    }
    if (!(vmax > 0)) vmax = 1;
    const View view;
    const Point2f c(left + kPanel / 2, full ? kTop + 190 : kTop + 250);
    const double S = full ? 150 : 175;
    Stroke disk{{}, palette::kMuted, 1, true};
    Fill plate{{}, palette::kGrid, 0.5f};
    for (int i = 0; i < 96; ++i) {
        double t = 2 * kPiD * i / 96;
        Point2f p = view.project(c, S, 1.1 * std::cos(t), 1.1 * std::sin(t), 0);
        disk.points.push_back(p);
        plate.points.push_back(p);
    }
    d.add(plate);
    d.add(disk);
    d.line(view.project(c, S, 0, 0, 0), view.project(c, S, 0, 0, 1.15), palette::kMuted, 1, 4);
    Vector3f wi = models[0].lobe.wi;
    arrow(d, view.project(c, S, 1.15 * wi.x, 1.15 * wi.y, 1.15 * wi.z), view.project(c, S, 0, 0, 0),
          palette::kLight, 2);
    for (std::size_t k = 0; k < models.size(); ++k) {
        const LobeGrid& g = models[k].lobe;
        auto point = [&](int r, int col) {
            Vector3f w = g.direction(r, col);
            double v = channel_mean(g.at(r, col)) / vmax;
            return view.project(c, S, v * w.x, v * w.y, v * w.z);
        };
        int sr = std::max(1, g.n_theta / 15), sc = std::max(1, g.n_phi / 36);
        Color3 colour = series(k);
        for (int r = sr / 2; r < g.rows(); r += sr) {
            Stroke s{{}, colour, 0.8f, true};
            for (int col = 0; col < g.n_phi; ++col) s.points.push_back(point(r, col));
            d.add(s);
        }
        for (int col = 0; col < g.n_phi; col += sc) {
            Stroke s{{}, colour, 0.8f};
            for (int r = 0; r < g.rows(); ++r) s.points.push_back(point(r, col));
            d.add(s);
        }
        for (const LobeSpike& sp : g.spikes) {
            Vector3f w = sp.direction;
            Point2f tip = view.project(c, S, w.x, w.y, w.z);
            arrow(d, view.project(c, S, 0, 0, 0), tip, colour, 2.5f);
            d.text({tip.x + 4, tip.y - 4 + 12.0f * float(k)}, fmt::format("δ {:.3f}", channel_mean(sp.share)),
                   11, TextAnchor::Start, colour);
        }
    }
    d.text({left + kPanel / 2, kTop + kPanelHeight + 2}, "I(ω) over the sphere: r = I(ω) ω", 12,
           TextAnchor::Middle, palette::kInk);
    d.text({left + kPanel / 2, kTop + kPanelHeight + 18},
           fmt::format("grid {}x{} per hemisphere, peak {} [1/sr]", models[0].lobe.n_theta,
                       models[0].lobe.n_phi, tick_label(vmax)),
           11, TextAnchor::Middle, palette::kMuted);
}

void albedo_panel(Drawing& d, const std::vector<BrdfPlotData>& models, float left, float kTop) {
    double top = 0;
    for (const auto& m : models)
        for (const AlbedoPoint& a : m.albedo) top = std::max(top, channel_mean(a.albedo));
    Axes ax;
    ax.left = left + 62;
    ax.top = kTop + 8;
    ax.width = kPanel - 80;
    ax.height = kPanelHeight - 60;
    ax.x0 = 0;
    ax.x1 = 90;
    ax.y0 = 0;
    ax.y1 = std::max(1.0, 1.08 * top);
    ax.draw(d, {0, 15, 30, 45, 60, 75, 90}, nice_ticks(0, ax.y1, 5), "θi [°]", "ρ(θi) = ∫ f |cos θ| dω");
    double ti = models[0].theta_i_deg;
    if (ti <= 90) d.line(ax.map(ti, ax.y0), ax.map(ti, ax.y1), palette::kLight, 1.5f, 4);
    for (std::size_t k = 0; k < models.size(); ++k) {
        Stroke total{{}, series(k), 2}, of_f{{}, series(k), 1.2f, false, 4};
        for (const AlbedoPoint& a : models[k].albedo) {
            total.points.push_back(ax.map(a.theta_deg, channel_mean(a.albedo)));
            of_f.points.push_back(ax.map(a.theta_deg, channel_mean(a.of_f)));
        }
        d.add(total);
        if (has_spikes(models[k])) d.add(of_f);
        if (ti <= 90) {
            Point2f p = ax.map(ti, channel_mean(models[k].lobe.albedo()));
            circle(d, p, 4, true, series(k), 2);
        }
    }
    d.text({left + kPanel / 2, kTop + kPanelHeight + 2}, "directional albedo: the integral of the lobe grid",
           12, TextAnchor::Middle, palette::kInk);
    d.text({left + kPanel / 2, kTop + kPanelHeight + 18}, "dashed: the part f() gives (without delta lobes)",
           11, TextAnchor::Middle, palette::kMuted);
}

nlohmann::json rgb(const Rgb64& c) { return nlohmann::json::array({c[0], c[1], c[2]}); }

} // namespace

std::vector<double> default_albedo_thetas() {
    std::vector<double> t;
    for (int i = 0; i <= 22; ++i) t.push_back(4.0 * i);
    return t;
}

BrdfPlotData brdf_plot_data(const BxDF& bxdf, std::string label, double theta_i_deg, double phi_i_deg,
                            const std::vector<double>& thetas, const LobeOptions& options) {
    BrdfPlotData m;
    m.label = std::move(label);
    m.theta_i_deg = theta_i_deg;
    m.phi_i_deg = phi_i_deg;
    Vector3f wi = direction_deg(theta_i_deg, phi_i_deg);
    m.lobe = sample_lobe(bxdf, wi, options);
    m.plane = lobe_in_plane(bxdf, wi);
    m.albedo = albedo_curve(bxdf, phi_i_deg, thetas, options);
    return m;
}

Drawing brdf_figure(const std::vector<BrdfPlotData>& models) {
    Drawing d;
    const float top = 62 + (models.size() > 1 ? 16.0f * float(models.size()) : 0.0f);
    d.width = int(3 * kPanel + 60);
    d.height = int(top + kPanelHeight + 34);
    if (models.empty()) return d;
    // The title names the models (their parameters too when they fit); a legend gives each in full.
    std::string title, names;
    for (const auto& m : models) {
        title += (title.empty() ? "" : "  vs  ") + m.label;
        names += (names.empty() ? "" : "  vs  ") + m.label.substr(0, m.label.find(' '));
    }
    d.text({20, 26}, text_width(title, 15) <= float(d.width) - 40 ? title : names, 15, TextAnchor::Start,
           palette::kInk);
    d.text({20, 46},
           fmt::format(
               "light arriving from θi = {:g}°, φi = {:g}°; I(ω) = f(ω, wi) |cos θ_ω|, the power scattered "
               "per steradian; ∫ I dω = ρ(θi)",
               models[0].theta_i_deg, models[0].phi_i_deg),
           12, TextAnchor::Start, palette::kMuted);
    if (models.size() > 1)
        for (std::size_t k = 0; k < models.size(); ++k) {
            float y = 61 + 16.0f * float(k);
            d.line({20, y}, {44, y}, series(k), 3);
            d.text({50, y + 4}, models[k].label, 12, TextAnchor::Start, series(k));
        }
    polar_panel(d, models, 20, top);
    mesh_panel(d, models, 20 + kPanel + 10, top);
    albedo_panel(d, models, 20 + 2 * (kPanel + 10), top);
    return d;
}

std::string brdf_plot_json(const std::vector<BrdfPlotData>& models) {
    nlohmann::json out;
    out["definition"] =
        "I(w) = f(w, wi) |cos theta_w| [1/sr]; albedo = integral of I over the sphere, midpoint "
        "grid plus delta spikes";
    out["models"] = nlohmann::json::array();
    for (const auto& m : models) {
        nlohmann::json j;
        j["label"] = m.label;
        j["theta_i"] = m.theta_i_deg;
        j["phi_i"] = m.phi_i_deg;
        j["grid"] = {{"n_theta", m.lobe.n_theta},
                     {"n_phi", m.lobe.n_phi},
                     {"both_hemispheres", m.lobe.both_hemispheres}};
        j["albedo_at_wi"] = rgb(m.lobe.albedo());
        j["albedo_of_f_at_wi"] = rgb(m.lobe.integral_of_f());
        j["spikes"] = nlohmann::json::array();
        for (const LobeSpike& s : m.lobe.spikes)
            j["spikes"].push_back(
                {{"direction", {s.direction.x, s.direction.y, s.direction.z}}, {"share", rgb(s.share)}});
        j["plane"] = nlohmann::json::array();
        for (const PlaneSample& p : m.plane)
            j["plane"].push_back({p.psi_deg, p.value[0], p.value[1], p.value[2]});
        j["albedo"] = nlohmann::json::array();
        j["albedo_of_f"] = nlohmann::json::array();
        for (const AlbedoPoint& a : m.albedo) {
            j["albedo"].push_back({a.theta_deg, a.albedo[0], a.albedo[1], a.albedo[2]});
            j["albedo_of_f"].push_back({a.theta_deg, a.of_f[0], a.of_f[1], a.of_f[2]});
        }
        out["models"].push_back(j);
    }
    return out.dump(1);
}

} // namespace illum

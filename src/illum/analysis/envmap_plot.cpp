#include "illum/analysis/envmap_plot.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/analysis/figure.h"
#include "illum/envmap/irradiance.h"
#include "illum/envmap/resample.h"
#include "illum/image/tonemap.h"

namespace illum {

namespace {

Image display(const Image& linear, double scale) {
    return tonemapped(linear, ToneMap::Aces, float(std::log2(scale)));
}

Image scaled(const Image& img, float s) {
    Image out = img;
    for (std::size_t i = 0; i < out.pixel_count(); ++i) out.data()[i] *= s;
    return out;
}

} // namespace

EnvmapFigure envmap_figure(const EnvironmentMap& map, const std::string& label,
                           const EnvmapFigureOptions& o) {
    EnvmapFigure fig;
    const int h = o.panel_height, w = 2 * h;
    EnvironmentMap radiance = resample(map, EnvLayout::LatLong, h);
    fig.sh = project_sh(map);
    Image sh_e = scaled(sh_irradiance_map(fig.sh, EnvLayout::LatLong, h).image(), float(1 / kPiD));
    EnvironmentMap bf =
        brute_force_irradiance(map, EnvLayout::LatLong, o.brute_force_height, o.brute_force_height);
    Image bf_e = scaled(bf.image(), float(1 / kPiD));

    // Mean |E_SH - E| / mean E, weighted by the brute-force texels' solid angles.
    double diff = 0, mean = 0;
    const auto& sa = bf.solid_angles();
    for (int y = 0; y < bf.height(); ++y)
        for (int x = 0; x < bf.width(); ++x) {
            auto n = bf.texel_direction(x, y);
            if (!n) continue;
            double ww = sa[std::size_t(y) * std::size_t(bf.width()) + std::size_t(x)];
            double e = bf.texel(x, y).average(), es = fig.sh.irradiance(*n).average();
            diff += ww * std::abs(es - e);
            mean += ww * e;
        }
    fig.sh_mean_difference = mean > 0 ? diff / mean : 0;

    double mean_e = bf_e.channel_mean().average();
    fig.exposure_scale = (o.auto_exposure && mean_e > 0 ? 0.5 / mean_e : 1.0) * std::exp2(o.exposure_stops);

    const float gap = 20, top = 70;
    Drawing& d = fig.drawing;
    d.width = int(3 * w + 4 * gap);
    d.height = int(top + h + 70);
    d.text({gap, 26}, label, 15, TextAnchor::Start, palette::kInk);
    d.text({gap, 46},
           fmt::format(
               "latitude-longitude, +z up at the top; exposure ×{:.4g}, ACES tone map; irradiance shown as "
               "E/π (the radiance of a white Lambertian surface facing n)",
               fig.exposure_scale),
           12, TextAnchor::Start, palette::kMuted);
    const char* titles[3] = {"radiance L", "SH irradiance E_SH/π (order 2, 9 coefficients)",
                             "brute-force irradiance E/π"};
    const Image* images[3] = {&radiance.image(), &sh_e, &bf_e};
    for (int i = 0; i < 3; ++i) {
        float x = gap + i * (w + gap);
        d.add(Picture{display(*images[i], fig.exposure_scale), x, top, float(w), float(h)});
        d.add(Stroke{{{x, top}, {x + w, top}, {x + w, top + h}, {x, top + h}}, palette::kInk, 1, true});
        d.text({x + w / 2.0f, top + h + 20}, titles[i], 12, TextAnchor::Middle, palette::kInk);
    }
    Color3 l00(float(fig.sh.c[0][0]), float(fig.sh.c[0][1]), float(fig.sh.c[0][2]));
    d.text(
        {gap, top + h + 48},
        fmt::format(
            "mean |E_SH − E| / mean E = {:.2f}% (on the {}x{} brute-force grid);  L00 = {:.4g} {:.4g} {:.4g}",
            100 * fig.sh_mean_difference, bf.width(), bf.height(), l00.r, l00.g, l00.b),
        12, TextAnchor::Start, palette::kInk);
    return fig;
}

} // namespace illum

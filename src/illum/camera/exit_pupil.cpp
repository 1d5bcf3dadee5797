#include "illum/camera/exit_pupil.h"

#include <algorithm>
#include <cmath>
#include <oneapi/tbb/parallel_for.h>

namespace illum {

void PupilBounds::extend(double x, double y) {
    if (empty()) {
        x0 = x1 = x;
        y0 = y1 = y;
        return;
    }
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
}

namespace {

// The radical inverse of i in base b (van der Corput): a low-discrepancy point set with base 2 and 3
// (Halton), covering the rear square evenly.
double radical_inverse(unsigned i, unsigned base) {
    double inv = 1.0 / base, f = inv, r = 0;
    for (; i > 0; i /= base, f *= inv) r += f * (i % base);
    return r;
}

// The targets of the bin's n rays, film point i to rear point i.
struct BinSample {
    double fx, px, py;
};
BinSample bin_sample(double r0, double r1, double half, int i, int n) {
    return {r0 + (r1 - r0) * (i + 0.5) / n, -half + 2 * half * radical_inverse(unsigned(i), 2),
            -half + 2 * half * radical_inverse(unsigned(i), 3)};
}

PupilBounds bound_bin(const LensSystem& lens, double r0, double r1, int n,
                      const std::vector<double>& lambdas) {
    const double half = 1.5 * lens.rear_aperture_radius(), z = lens.film_distance();
    auto passes = [&](const BinSample& s, double lambda) {
        return lens.trace_from_film(LensRay{{s.fx, 0, 0}, {s.px - s.fx, s.py, z}}, lambda, nullptr) > 0;
    };
    // The first wavelength (the d line) over every sample; a target already inside the box need not be
    // traced.
    PupilBounds b;
    for (int i = 0; i < n; ++i) {
        BinSample s = bin_sample(r0, r1, half, i, n);
        if (!b.contains(s.px, s.py) && passes(s, lambdas[0])) b.extend(s.px, s.py);
    }
    // The others move the pupil's rim by the dispersion's share of the lens's power (~3% of it over 360 to
    // 830 nm), so only targets within 15% of the rear radius of the first box can pass at them.
    if (!b.empty() && lambdas.size() > 1) {
        const double margin = 0.1 * half;
        PupilBounds near{b.x0 - margin, b.y0 - margin, b.x1 + margin, b.y1 + margin};
        for (int i = 0; i < n; ++i) {
            BinSample s = bin_sample(r0, r1, half, i, n);
            if (b.contains(s.px, s.py) || !near.contains(s.px, s.py)) continue;
            for (std::size_t k = 1; k < lambdas.size(); ++k)
                if (passes(s, lambdas[k])) {
                    b.extend(s.px, s.py);
                    break;
                }
        }
    }
    if (b.empty()) return b;
    double grow = 2 * (2 * half * std::sqrt(2.0)) / std::sqrt(double(n));
    b.x0 -= grow, b.y0 -= grow, b.x1 += grow, b.y1 += grow;
    return b;
}

} // namespace

ExitPupil::ExitPupil(const LensSystem& lens, double film_radius, int bins, int samples,
                     const std::vector<double>& lambdas)
    : bounds_(std::size_t(bins)), film_radius_(film_radius), rear_z_(lens.film_distance()) {
    tbb::parallel_for(0, bins, [&](int i) {
        bounds_[std::size_t(i)] =
            bound_bin(lens, film_radius * i / bins, film_radius * (i + 1) / bins, samples, lambdas);
    });
}

int ExitPupil::bin_of(double film_r) const {
    int i = int(film_r / film_radius_ * bins());
    return std::clamp(i, 0, bins() - 1);
}

std::optional<PupilSample> ExitPupil::sample(double x, double y, Point2f u) const {
    double r = std::sqrt(x * x + y * y);
    const PupilBounds& b = bounds_[std::size_t(bin_of(r))];
    if (b.empty()) return std::nullopt;
    double px = b.x0 + (b.x1 - b.x0) * u.x, py = b.y0 + (b.y1 - b.y0) * u.y;
    double c = r > 0 ? x / r : 1, s = r > 0 ? y / r : 0; // rotate from the +x axis to the point's angle
    return PupilSample{{c * px - s * py, s * px + c * py, rear_z_}, 1 / b.area()};
}

} // namespace illum

// illum_rgb2spec_opt: computes the RGB -> sigmoid-polynomial tables of Jakob & Hanika 2019 §5 for the four
// named colour spaces (rgb_to_spectrum.h) and writes <out>/<space>.bin, which rgb_to_spectrum.cpp embeds.
// The build runs it (cmake/rgb2spec.cmake); it takes a few seconds per space.
//
//   illum_rgb2spec_opt <out dir> [--space NAME] [--res N] [--residual rgb|lab] [--step NM]
//                      [--coarse-step NM] [--bound B] [--alpha A] [--check]
//
// 1. Each entry is fitted by SigmoidFit's Levenberg-Marquardt on a 5 nm grid, then moved to the fine
//    grid every RGB <-> spectrum conversion uses (integrate_spectrum, 1 nm) by chord steps: each costs
//    one evaluation, a fifth of the cost of fitting on the fine grid outright.
// 2. The order is the paper's: the centre of each table first (z ≈ 1/2, x = y = 1/2, from the
//    coefficients 0, the grey 1/2), then outwards, every entry starting from its solved neighbour towards
//    the centre in the same z layer or from the same (x, y) in the previous layer, whichever fits better,
//    and from the other too if the first does not converge. z layers are sequential; in each the centre
//    row is solved first, then the columns in parallel (oneTBB), the three tables side by side.
// 3. The z = 0 layer is black, which no finite polynomial reaches; it copies the z_1 layer
//    (z_1 = smoothstep(smoothstep(1/63)) ≈ 1.7e-6, so colours that interpolate to it are that dark).
//    x and y are on RGBToSpectrumTable::xy_node's grid; every entry is fitted (also those of the brighter
//    half, which the lookup reaches through the complement: the other half's cells and the correction
//    use them).
// 4. One pass moves each node by -alpha times the mean interpolation error at the centres of its cells
//    (TableSolver::correct_table): measured on sRGB, it lowers the round trip's largest error over
//    [0.02, 0.98]³ (71³ points) from 1.55e-3 to 6.5e-4 (alpha 0.3: 8.8e-4, 0.5: 8.4e-4; a second pass
//    made it worse). Measured with the x/y grid dense near 0 and the complement lookup
//    (rgb_to_spectrum.h), it brings [0, 1]³ from 1.3e-3 (73³, 12 points above 1e-3) to 3.4e-4. Leaving
//    the nodes on the cube's edges alone too made it 5.6e-4.
// --check prints the round-trip error of the tables just computed (lookup, then the fine quadrature).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "illum/radiometry/color_space.h"
#include "illum/radiometry/rgb_to_spectrum.h"
#include "illum/radiometry/sigmoid_fit.h"

using namespace illum;

namespace {

using Coeffs = std::array<double, 3>;

struct Options {
    std::string out, only;
    int res = RGBToSpectrumTable::kResolution;
    FitResidual residual = FitResidual::rgb;
    double step = kSpectralStepNm, coarse_step = 5;
    double tolerance = 1e-7; // an entry's RGB error to stop at
    double bound = SigmoidFit::kBound;
    double alpha = 0.4; // correct_table's shift
    bool check = false;
};

struct Stats {
    std::atomic<long> entries{0}, iterations{0}, fine_steps{0}, unconverged{0};
};

constexpr float kUnreachable = 1e-5f; // an entry's error above which its target counts as out of reach

class TableSolver {
public:
    TableSolver(const SigmoidFit& coarse, const SigmoidFit& fine, const Options& opt, Stats& stats)
        : coarse_(coarse), fine_(fine), opt_(opt), res_(opt.res), stats_(stats),
          c_(std::size_t(9) * res_ * res_ * res_), err_(std::size_t(3) * res_ * res_ * res_), z_(res_) {
        for (int k = 0; k < res_; ++k) z_[k] = float(RGBToSpectrumTable::z_node(k, res_));
    }

    void solve_all() {
        tbb::parallel_for(0, 3, [&](int i) {
            solve_table(i);
            if (opt_.alpha > 0) correct_table(i);
            for (int y = 0; y < res_; ++y)
                for (int x = 0; x < res_; ++x) at(i, 0, y, x) = at(i, 1, y, x);
        });
    }

    const std::vector<float>& z() const { return z_; }
    Coeffs& at(int i, int k, int y, int x) {
        return *reinterpret_cast<Coeffs*>(&c_[RGBToSpectrumTable::offset(i, k, y, x, res_)]);
    }
    float worst_error() const { return *std::max_element(err_.begin(), err_.end()); }

private:
    float& error(int i, int k, int y, int x) {
        return err_[RGBToSpectrumTable::offset(i, k, y, x, res_) / 3];
    }

    // The colour at lookup coordinates (z, x, y) of table i (rgb_to_spectrum.h).
    static Coeffs colour(int i, double z, double x, double y) {
        Coeffs rgb{};
        rgb[i] = z;
        rgb[(i + 1) % 3] = z * x;
        rgb[(i + 2) % 3] = z * y;
        return rgb;
    }
    Coeffs target(int i, int k, int y, int x) const {
        return colour(i, z_[k], RGBToSpectrumTable::xy_node(double(x) / (res_ - 1)),
                      RGBToSpectrumTable::xy_node(double(y) / (res_ - 1)));
    }

    // Entry (i, k, y, x) from start a, and from b if a does not converge; then on the fine grid.
    void solve(int i, int k, int y, int x, const Coeffs* a, const Coeffs* b) {
        Coeffs t = target(i, k, y, x);
        SigmoidFit::Result r = coarse_.solve(t, a ? *a : Coeffs{0, 0, 0}, opt_.tolerance, 100, opt_.bound);
        long iterations = r.iterations;
        if (r.rgb_error > opt_.tolerance && b) {
            SigmoidFit::Result r2 = coarse_.solve(t, *b, opt_.tolerance, 100, opt_.bound);
            iterations += r2.iterations;
            if (r2.rgb_error < r.rgb_error) r = r2;
        }
        if (&fine_ != &coarse_) {
            r = fine_.refine(t, r.c, coarse_, opt_.tolerance, 4, opt_.bound);
            stats_.fine_steps += r.iterations;
        }
        at(i, k, y, x) = r.c;
        error(i, k, y, x) = float(r.rgb_error);
        stats_.entries += 1;
        stats_.iterations += iterations;
        if (r.rgb_error > 1e-6) stats_.unconverged += 1;
    }

    // The start that fits better of two (either may be missing) first.
    std::pair<const Coeffs*, const Coeffs*> order(int i, int k, int y, int x, const Coeffs* a,
                                                  const Coeffs* b) {
        if (!a || !b) return {a ? a : b, nullptr};
        Coeffs t = target(i, k, y, x);
        auto err = [&](const Coeffs& c) {
            double v[3];
            coarse_.rgb(c, v);
            return std::abs(v[0] - t[0]) + std::abs(v[1] - t[1]) + std::abs(v[2] - t[2]);
        };
        return err(*a) <= err(*b) ? std::pair{a, b} : std::pair{b, a};
    }

    void solve_layer(int i, int k, int prev) {
        const int c = res_ / 2;
        auto run = [&](int y, int x, const Coeffs* neighbour) {
            auto [a, b] = order(i, k, y, x, neighbour, prev < 0 ? nullptr : &at(i, prev, y, x));
            solve(i, k, y, x, a, b);
        };
        run(c, c, nullptr);
        for (int x = c + 1; x < res_; ++x) run(c, x, &at(i, k, c, x - 1));
        for (int x = c - 1; x >= 0; --x) run(c, x, &at(i, k, c, x + 1));
        tbb::parallel_for(0, res_, [&](int x) {
            for (int y = c + 1; y < res_; ++y) run(y, x, &at(i, k, y - 1, x));
            for (int y = c - 1; y >= 0; --y) run(y, x, &at(i, k, y + 1, x));
        });
    }

    void solve_table(int i) {
        const int k0 = res_ / 2;
        solve_layer(i, k0, -1);
        for (int k = k0 + 1; k < res_; ++k) solve_layer(i, k, k - 1);
        for (int k = k0 - 1; k >= 1; --k) solve_layer(i, k, k + 1);
    }

    // Between nodes the trilinear interpolation of coefficients bends away from the target, most at a
    // cell's centre, with the sign of the coefficients' curvature. Moving every node by -alpha times the
    // mean error at the centres of its (up to 8) cells spreads that error over nodes and centres (for a
    // parabola alpha = 1/2 halves the largest error, the best a linear interpolant does in the max norm).
    // The move is one chord step to the node's current colour on the coarse grid minus that shift, kept
    // only where it lands within 10% (not where S saturates, near white). Cells with an unreachable
    // corner, and unreachable nodes, are left alone; so are the cube's corners (the primaries, the
    // secondaries and white), which stay exact instead of taking 1e-3 from their cells (sRGB's blue).
    // Measured on sRGB's 73³ grid, this keeps the points above 1e-3 at 141 (all but one with a component
    // 1), where leaving the whole top z layer alone would make them 430.
    void correct_table(int i) {
        const int n = res_ - 1; // cells per axis
        auto cell = [&](int k, int y, int x) { return (std::size_t(k) * n + y) * n + x; };
        std::vector<Coeffs> centre(std::size_t(n) * n * n);
        std::vector<char> valid(centre.size(), 0);
        tbb::parallel_for(1, n, [&](int k) {
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    Coeffs m{0, 0, 0};
                    bool ok = true;
                    for (int corner = 0; corner < 8; ++corner) {
                        int ox = corner & 1, oy = (corner >> 1) & 1, oz = corner >> 2;
                        ok = ok && error(i, k + oz, y + oy, x + ox) < kUnreachable;
                        const Coeffs& c = at(i, k + oz, y + oy, x + ox);
                        for (int q = 0; q < 3; ++q) m[q] += c[q] / 8;
                    }
                    if (!ok) continue;
                    Coeffs t = colour(i, 0.5 * (double(z_[k]) + z_[k + 1]),
                                      RGBToSpectrumTable::xy_node((x + 0.5) / n),
                                      RGBToSpectrumTable::xy_node((y + 0.5) / n));
                    double v[3];
                    fine_.rgb(m, v);
                    for (int q = 0; q < 3; ++q) centre[cell(k, y, x)][q] = v[q] - t[q];
                    valid[cell(k, y, x)] = 1;
                }
        });
        auto cube_corner = [&](int k, int y, int x) {
            return k == res_ - 1 && (x == 0 || x == res_ - 1) && (y == 0 || y == res_ - 1);
        };
        tbb::parallel_for(1, res_, [&](int k) {
            for (int y = 0; y < res_; ++y)
                for (int x = 0; x < res_; ++x) {
                    if (!(error(i, k, y, x) < kUnreachable) || cube_corner(k, y, x)) continue;
                    double mean[3] = {0, 0, 0};
                    int count = 0;
                    for (int corner = 0; corner < 8; ++corner) {
                        int ck = k - (corner >> 2), cy = y - ((corner >> 1) & 1), cx = x - (corner & 1);
                        if (ck < 1 || cy < 0 || cx < 0 || ck >= n || cy >= n || cx >= n) continue;
                        if (!valid[cell(ck, cy, cx)]) continue;
                        for (int q = 0; q < 3; ++q) mean[q] += centre[cell(ck, cy, cx)][q];
                        ++count;
                    }
                    if (count == 0) continue;
                    Coeffs& c = at(i, k, y, x);
                    double v[3], shift = 0;
                    coarse_.rgb(c, v);
                    Coeffs moved_to;
                    for (int q = 0; q < 3; ++q) {
                        moved_to[q] = v[q] - opt_.alpha * mean[q] / count;
                        shift = std::max(shift, std::abs(moved_to[q] - v[q]));
                    }
                    SigmoidFit::Result r = coarse_.refine(moved_to, c, coarse_, 0, 1, opt_.bound);
                    if (r.iterations == 1 && r.rgb_error < 0.1 * shift + 1e-7) c = r.c;
                }
        });
    }

    const SigmoidFit &coarse_, &fine_;
    const Options& opt_;
    int res_;
    Stats& stats_;
    std::vector<double> c_;
    std::vector<float> err_, z_;
};

// The round trip over an n³ grid of [lo, hi]³: lookup, then the fit's quadrature of the float polynomial.
void check(const SigmoidFit& fit, const RGBToSpectrumTable& table, int n, double lo, double hi) {
    std::vector<double> worst(n, 0);
    std::vector<Coeffs> where(n);
    std::vector<long> over(n, 0);
    tbb::parallel_for(0, n, [&](int a) {
        for (int b = 0; b < n; ++b)
            for (int c = 0; c < n; ++c) {
                Color3 rgb(float(lo + (hi - lo) * a / (n - 1)), float(lo + (hi - lo) * b / (n - 1)),
                           float(lo + (hi - lo) * c / (n - 1)));
                double v[3];
                fit.rgb(table.lookup(rgb), v);
                double e = std::max({std::abs(v[0] - rgb.r), std::abs(v[1] - rgb.g), std::abs(v[2] - rgb.b)});
                if (e > worst[a]) worst[a] = e, where[a] = {rgb.r, rgb.g, rgb.b};
                over[a] += e > 1e-3;
            }
    });
    int w = int(std::max_element(worst.begin(), worst.end()) - worst.begin());
    long o = 0;
    for (long v : over) o += v;
    std::printf("  round trip over [%.2f, %.2f]^3 (%d^3): max error %.3g at (%.4f, %.4f, %.4f), %ld points "
                "above 1e-3\n",
                lo, hi, n, worst[w], where[w][0], where[w][1], where[w][2], o);
}

bool write_table(const std::string& path, int res, const std::vector<float>& data) {
    RGBToSpectrumFileHeader header;
    header.res = std::uint32_t(res);
    header.floats = std::uint32_t(data.size());
    std::string tmp = path + ".tmp";
    {
        std::ofstream f(tmp, std::ios::binary);
        f.write(reinterpret_cast<const char*>(&header), sizeof header);
        f.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * sizeof(float)));
        if (!f) return false;
    }
    return std::rename(tmp.c_str(), path.c_str()) == 0;
}

bool parse(int argc, char** argv, Options& o) {
    for (int a = 1; a < argc; ++a) {
        std::string arg = argv[a];
        bool more = a + 1 < argc;
        if (arg == "--res" && more)
            o.res = std::atoi(argv[++a]);
        else if (arg == "--residual" && more) {
            std::string v = argv[++a];
            if (v != "rgb" && v != "lab") return false;
            o.residual = v == "lab" ? FitResidual::lab : FitResidual::rgb;
        } else if (arg == "--step" && more)
            o.step = std::atof(argv[++a]);
        else if (arg == "--coarse-step" && more)
            o.coarse_step = std::atof(argv[++a]);
        else if (arg == "--bound" && more)
            o.bound = std::atof(argv[++a]);
        else if (arg == "--alpha" && more)
            o.alpha = std::atof(argv[++a]);
        else if (arg == "--space" && more)
            o.only = argv[++a];
        else if (arg == "--check")
            o.check = true;
        else if (o.out.empty() && arg[0] != '-')
            o.out = arg;
        else
            return false;
    }
    return !o.out.empty() && o.res >= 4 && o.step > 0 && o.bound > 0;
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!parse(argc, argv, opt)) {
        std::fprintf(stderr,
                     "usage: illum_rgb2spec_opt <out dir> [--space NAME] [--res N] [--residual rgb|lab] "
                     "[--step NM] [--coarse-step NM] [--bound B] [--alpha A] [--check]\n");
        return 2;
    }
    auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < RGBColorSpace::kCount; ++s) {
        const RGBColorSpace& space = RGBColorSpace::by_index(s);
        if (!opt.only.empty() && space.name() != opt.only) continue;
        auto t1 = std::chrono::steady_clock::now();
        SigmoidFit fit(space, opt.residual, opt.step);
        std::unique_ptr<SigmoidFit> coarse;
        if (opt.coarse_step > opt.step)
            coarse = std::make_unique<SigmoidFit>(space, opt.residual, opt.coarse_step);
        Stats stats;
        TableSolver solver(coarse ? *coarse : fit, fit, opt, stats);
        solver.solve_all();

        // λ in nm, float: the layout RGBToSpectrumTable reads.
        const int res = opt.res;
        std::vector<float> data(solver.z());
        data.resize(std::size_t(res) + std::size_t(9) * res * res * res);
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < res; ++k)
                for (int y = 0; y < res; ++y)
                    for (int x = 0; x < res; ++x) {
                        RGBSigmoidPolynomial p = SigmoidFit::to_nm(solver.at(i, k, y, x));
                        float* e = &data[res + RGBToSpectrumTable::offset(i, k, y, x, res)];
                        e[0] = p.c0, e[1] = p.c1, e[2] = p.c2;
                    }
        std::string path = opt.out + "/" + std::string(space.name()) + ".bin";
        if (!write_table(path, res, data)) {
            std::fprintf(stderr, "illum_rgb2spec_opt: cannot write %s\n", path.c_str());
            return 1;
        }
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
        std::printf("%s: %ld entries, %.2f + %.2f iterations each, %ld (out of reach) not within 1e-6 "
                    "(worst %.3g), %.2f s\n",
                    std::string(space.name()).c_str(), stats.entries.load(),
                    double(stats.iterations) / double(stats.entries),
                    double(stats.fine_steps) / double(stats.entries), stats.unconverged.load(),
                    double(solver.worst_error()), secs);
        if (opt.check) {
            RGBToSpectrumTable table{res, data.data(), data.data() + res};
            check(fit, table, 73, 0, 1);
            check(fit, table, 145, 0, 1);
            check(fit, table, 71, 0.02, 0.98);
        }
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("illum_rgb2spec_opt: %.2f s\n", secs);
    return 0;
}
